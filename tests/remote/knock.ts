// Opens the WebSocket door of a HAL server as a browser page or a program would, and says what
// the door did: let the client in (the hello's role), or refuse the upgrade (status and reason).
import { WebSocket } from 'ws';

/** What the door did with one client. */
export type Knock =
  { opened: true; role: string } | { opened: false; status: number; body: string };

/**
 * Connects to `url` with `headers` (an `Origin` as a browser sends one, a `Host`, a token) and
 * resolves with the hello's role, or with the HTTP status and body of a refused upgrade. Rejects on
 * any other outcome, or after 10 s.
 */
export function knock(url: string, headers: Record<string, string> = {}): Promise<Knock> {
  const socket = new WebSocket(url, { headers });
  return new Promise<Knock>((resolve, reject) => {
    const timer = setTimeout(() => {
      socket.terminate();
      reject(new Error(`neither a hello nor a refusal from ${url} within 10000 ms`));
    }, 10_000);
    const done = (outcome: Knock | Error) => {
      clearTimeout(timer);
      socket.removeAllListeners();
      socket.on('error', () => undefined);
      if (outcome instanceof Error) reject(outcome);
      else resolve(outcome);
    };
    socket.on('unexpected-response', (_request, response) => {
      let body = '';
      response.setEncoding('utf8');
      response.on('data', (chunk: string) => (body += chunk));
      response.on('end', () => {
        done({ opened: false, status: response.statusCode ?? 0, body });
        socket.terminate();
      });
    });
    socket.on('message', (data) => {
      const message = JSON.parse(String(data)) as {
        schema: string;
        payload: { role?: string };
      };
      if (message.schema !== 'hal.remote.hello') return;
      done({ opened: true, role: message.payload.role ?? '' });
      socket.close();
    });
    socket.on('error', (error) => done(error));
  });
}
