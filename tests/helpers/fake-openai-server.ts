// A local stand-in for an OpenAI-compatible chat-completions server, for the tests of the LLM
// decision provider and the agent loop: it answers POST /v1/chat/completions from a script of
// replies and records each request. It allows CORS, so a page on another origin can call it.
import { createServer } from 'node:http';
import type { IncomingHttpHeaders, Server, ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';

/** A tool call in a scripted reply; `arguments` is sent as written (it may be broken JSON). */
export interface ScriptedToolCall {
  name: string;
  arguments: string;
  id?: string;
}

/** One scripted reply. */
export type ScriptedReply =
  /** A chat completion whose message content is this text (or these text parts), maybe with tool calls. */
  | { content: string | { type: 'text'; text: string }[] | null; toolCalls?: ScriptedToolCall[] }
  /** A chat completion whose message refuses (the `refusal` field). */
  | { refusal: string }
  /** An HTTP error status with this body (and these headers, e.g. Retry-After). */
  | { status: number; body: string; headers?: Record<string, string> }
  /** Never answer (until the server closes). */
  | { hang: true };

export interface RecordedRequest {
  path: string;
  headers: IncomingHttpHeaders;
  /** When it arrived (Date.now()). */
  at: number;
  body: {
    model?: string;
    messages?: { role: string; content: unknown; [key: string]: unknown }[];
    tools?: {
      type: string;
      function: { name: string; description: string; parameters: unknown };
    }[];
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

const CORS = {
  'access-control-allow-origin': '*',
  'access-control-allow-methods': 'POST, OPTIONS',
  'access-control-allow-headers': 'authorization, content-type',
};

function completion(reply: ScriptedReply, n: number, model: string): Record<string, unknown> {
  const message =
    'refusal' in reply
      ? { role: 'assistant', content: null, refusal: reply.refusal }
      : 'content' in reply
        ? {
            role: 'assistant',
            content: reply.content,
            ...(reply.toolCalls === undefined
              ? {}
              : {
                  tool_calls: reply.toolCalls.map((call, i) => ({
                    id: call.id ?? `call_${n}_${i}`,
                    type: 'function',
                    function: { name: call.name, arguments: call.arguments },
                  })),
                }),
          }
        : {};
  const toolCalls = 'toolCalls' in reply && (reply.toolCalls?.length ?? 0) > 0;
  return {
    id: `chatcmpl-${n}`,
    object: 'chat.completion',
    created: 0,
    model,
    choices: [{ index: 0, message, finish_reason: toolCalls ? 'tool_calls' : 'stop' }],
  };
}

function send(res: ServerResponse, status: number, body: string, headers = {}): void {
  res.writeHead(status, { 'content-type': 'application/json', ...CORS, ...headers });
  res.end(body);
}

export async function startFakeOpenAIServer(script: ScriptedReply[]): Promise<FakeOpenAIServer> {
  const requests: RecordedRequest[] = [];
  const state = { script: [...script], last: script.at(-1) };
  const hanging = new Set<() => void>();
  const server: Server = createServer((req, res) => {
    if (req.method === 'OPTIONS') {
      res.writeHead(204, { ...CORS, 'access-control-max-age': '600' });
      res.end();
      return;
    }
    const chunks: Buffer[] = [];
    req.on('data', (c: Buffer) => chunks.push(c));
    req.on('end', () => {
      let body: RecordedRequest['body'] = {};
      try {
        body = JSON.parse(Buffer.concat(chunks).toString('utf8')) as RecordedRequest['body'];
      } catch {
        body = {};
      }
      requests.push({ path: req.url ?? '', headers: req.headers, at: Date.now(), body });
      if (req.method !== 'POST' || req.url !== '/v1/chat/completions') {
        send(res, 404, JSON.stringify({ error: { message: 'not found' } }));
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
        send(res, reply.status, reply.body, reply.headers);
        return;
      }
      send(res, 200, JSON.stringify(completion(reply, requests.length, body.model ?? 'unknown')));
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
