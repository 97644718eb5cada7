// A local stand-in for an OpenAI-compatible chat-completions server, for the LLM provider's
// tests: it answers POST /v1/chat/completions from a script of replies and records each request.
import { createServer } from 'node:http';
import type { IncomingHttpHeaders, Server } from 'node:http';
import type { AddressInfo } from 'node:net';

/** One scripted reply. */
export type ScriptedReply =
  /** A chat completion whose message content is this text (or these text parts). */
  | { content: string | { type: 'text'; text: string }[] }
  /** An HTTP error status with this body. */
  | { status: number; body: string }
  /** Never answer (until the server closes). */
  | { hang: true };

export interface RecordedRequest {
  path: string;
  headers: IncomingHttpHeaders;
  body: {
    model?: string;
    messages?: { role: string; content: unknown }[];
    response_format?: {
      type: string;
      json_schema?: { name: string; schema: unknown; strict?: boolean };
    };
    [key: string]: unknown;
  };
}

export interface FakeOpenAIServer {
  /** Base URL including /v1. */
  baseUrl: string;
  requests: RecordedRequest[];
  /** Replies still to give; the last one repeats when the script runs out. */
  script: ScriptedReply[];
  close(): Promise<void>;
}

export async function startFakeOpenAIServer(script: ScriptedReply[]): Promise<FakeOpenAIServer> {
  const requests: RecordedRequest[] = [];
  const state = { script: [...script], last: script.at(-1) };
  const hanging = new Set<() => void>();
  const server: Server = createServer((req, res) => {
    const chunks: Buffer[] = [];
    req.on('data', (c: Buffer) => chunks.push(c));
    req.on('end', () => {
      let body: RecordedRequest['body'] = {};
      try {
        body = JSON.parse(Buffer.concat(chunks).toString('utf8')) as RecordedRequest['body'];
      } catch {
        body = {};
      }
      requests.push({ path: req.url ?? '', headers: req.headers, body });
      if (req.method !== 'POST' || req.url !== '/v1/chat/completions') {
        res.writeHead(404, { 'content-type': 'application/json' });
        res.end(JSON.stringify({ error: { message: 'not found' } }));
        return;
      }
      const reply = state.script.shift() ?? state.last;
      if (reply === undefined || 'hang' in reply) {
        const release = () => res.destroy();
        hanging.add(release);
        res.on('close', () => hanging.delete(release));
        return;
      }
      if ('status' in reply) {
        res.writeHead(reply.status, { 'content-type': 'application/json' });
        res.end(reply.body);
        return;
      }
      res.writeHead(200, { 'content-type': 'application/json' });
      res.end(
        JSON.stringify({
          id: `chatcmpl-${requests.length}`,
          object: 'chat.completion',
          created: 0,
          model: body.model ?? 'unknown',
          choices: [
            {
              index: 0,
              message: { role: 'assistant', content: reply.content },
              finish_reason: 'stop',
            },
          ],
        }),
      );
    });
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    baseUrl: `http://127.0.0.1:${port}/v1`,
    requests,
    get script() {
      return state.script;
    },
    set script(next: ScriptedReply[]) {
      state.script = [...next];
      state.last = next.at(-1);
    },
    close: () =>
      new Promise<void>((resolve) => {
        for (const release of hanging) release();
        server.closeAllConnections();
        server.close(() => resolve());
      }),
  };
}
