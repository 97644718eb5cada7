// Talks to the robot over UDP as any program on the network could: seed-style requests (no
// session, so they take nothing away from the host that holds the session), such as `get_status`.
import { createSocket } from 'node:dgram';

/** A status reply and when it arrived, on this process's `performance.now()` clock. */
export interface Probe {
  status: Record<string, unknown> & {
    uptime_ms: number;
    running: boolean;
    move_outcome: string;
    left_steps: number;
    right_steps: number;
    move_id: number;
    safety: Record<string, unknown> & {
      estop: boolean;
      trips: number;
      last_trip: { reason: string; detail: string; uptime_ms: number } | null;
      coils_on: boolean;
    };
  };
  receivedAt: number;
}

/** Sends `get_status` to 127.0.0.1:`port`, resent every 200 ms, up to `timeoutMs` in all. */
export async function probeStatus(port: number, timeoutMs = 3000): Promise<Probe> {
  const socket = createSocket('udp4');
  try {
    await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
    return await new Promise<Probe>((resolve, reject) => {
      const send = () => socket.send('{"cmd":"get_status"}', port, '127.0.0.1');
      const resend = setInterval(send, 200);
      const timer = setTimeout(() => {
        clearInterval(resend);
        reject(new Error(`no get_status reply from 127.0.0.1:${port} within ${timeoutMs} ms`));
      }, timeoutMs);
      socket.on('message', (message) => {
        const receivedAt = performance.now();
        const reply = JSON.parse(message.toString()) as Probe['status'] & { ok?: boolean };
        if (reply.ok !== true || reply['cmd'] !== 'get_status') return;
        clearInterval(resend);
        clearTimeout(timer);
        resolve({ status: reply, receivedAt });
      });
      send();
    });
  } finally {
    socket.close();
  }
}

/** Sends one seed-style request to 127.0.0.1:`port` (never resent); resolves its reply. */
export async function seedRequest(
  port: number,
  body: Record<string, unknown> & { cmd: string },
  timeoutMs = 5000,
): Promise<Record<string, unknown>> {
  const socket = createSocket('udp4');
  try {
    await new Promise<void>((resolve) => socket.bind(0, '127.0.0.1', resolve));
    return await new Promise((resolve, reject) => {
      const timer = setTimeout(
        () =>
          reject(
            new Error(`no reply to ${body.cmd} from 127.0.0.1:${port} within ${timeoutMs} ms`),
          ),
        timeoutMs,
      );
      socket.once('message', (message) => {
        clearTimeout(timer);
        resolve(JSON.parse(message.toString()) as Record<string, unknown>);
      });
      socket.send(JSON.stringify(body), port, '127.0.0.1');
    });
  } finally {
    socket.close();
  }
}
