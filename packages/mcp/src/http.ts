import { timingSafeEqual } from 'node:crypto';
import { createServer } from 'node:http';
import type { IncomingMessage, Server as HttpServer, ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import type { Server } from '@modelcontextprotocol/sdk/server/index.js';
import { StreamableHTTPServerTransport } from '@modelcontextprotocol/sdk/server/streamableHttp.js';
import { browserRefusal, isLoopback } from '@hal/runtime';
import { errorMessage } from '@hal/types';
import { DEFAULT_MAX_SESSIONS, httpSessions } from './http-sessions.js';

/** Where and how the streamable HTTP endpoint listens. */
export interface HttpOptions {
  /** Address to bind, default 127.0.0.1. Any other than loopback requires `token`. */
  host?: string;
  /** Port, default 3333; 0 picks a free one. */
  port?: number;
  /** Bearer token every request must carry (`Authorization: Bearer <token>`). */
  token?: string;
  /** Path of the endpoint, default `/mcp`. */
  path?: string;
  /**
   * Sessions (`Mcp-Session-Id`): a client's server lasts from its initialize to its DELETE, and
   * can ask it questions (approval), send progress, resource updates and log lines. Default
   * false: stateless, every POST a complete exchange answered as one JSON response.
   */
  sessions?: boolean;
  /** With sessions: how many may be open at once (default 16); a new one closes the least recently used. */
  maxSessions?: number;
}

/** A listening endpoint. */
export interface HttpEndpoint {
  url: string;
  port: number;
  close(): Promise<void>;
}

function sameToken(given: string, expected: string): boolean {
  const a = Buffer.from(given);
  const b = Buffer.from(expected);
  return a.length === b.length && timingSafeEqual(a, b);
}

function refuse(res: ServerResponse, status: number, message: string): void {
  res.writeHead(status, { 'content-type': 'application/json' });
  res.end(JSON.stringify({ jsonrpc: '2.0', error: { code: -32000, message }, id: null }));
}

/** Why a request is refused before it reaches MCP, or undefined. */
function gate(req: IncomingMessage, options: Required<Pick<HttpOptions, 'path'>> & HttpOptions) {
  const url = new URL(req.url ?? '/', 'http://localhost');
  if (url.pathname !== options.path)
    return [404, `not found; the endpoint is ${options.path}`] as const;
  if (options.token !== undefined) {
    const auth = req.headers.authorization ?? '';
    const given = auth.startsWith('Bearer ') ? auth.slice(7) : '';
    if (!sameToken(given, options.token)) return [401, 'a valid bearer token is required'] as const;
    return undefined;
  }
  // Without a token, only this machine may call: programs, and pages served from it; not a page
  // from another site, nor one that reaches it by DNS rebinding (the door serveHal keeps too).
  const refused = browserRefusal(req.headers);
  if (refused !== undefined) return [403, `${refused.reason}: a token is needed`] as const;
  return undefined;
}

/**
 * Serves MCP over streamable HTTP: stateless (each request gets a fresh server from `create`), or
 * with `sessions` (a server per session); all of them drive the same HAL. Refuses to start on a
 * non-loopback address without a token.
 */
export async function serveHttp(
  create: () => Server,
  options: HttpOptions = {},
): Promise<HttpEndpoint> {
  const host = options.host ?? '127.0.0.1';
  const settings = { ...options, path: options.path ?? '/mcp' };
  if (!isLoopback(host) && (options.token === undefined || options.token.length < 16)) {
    throw new Error(
      `refusing to listen on ${host} without a token of at least 16 characters: ` +
        'any other address than 127.0.0.1 needs --token',
    );
  }
  const sessions =
    options.sessions === true
      ? httpSessions(create, refuse, options.maxSessions ?? DEFAULT_MAX_SESSIONS)
      : undefined;
  const http: HttpServer = createServer((req, res) => {
    const refusal = gate(req, settings);
    if (refusal !== undefined) return refuse(res, refusal[0], refusal[1]);
    if (sessions !== undefined) {
      sessions.handle(req, res).catch((error: unknown) => {
        if (!res.headersSent) refuse(res, 500, errorMessage(error));
      });
      return;
    }
    if (req.method !== 'POST') return refuse(res, 405, 'this endpoint is stateless: POST only');
    const server = create();
    // no sessionIdGenerator: stateless, every request stands alone
    const transport = new StreamableHTTPServerTransport({
      enableJsonResponse: true,
    });
    res.on('close', () => {
      void transport.close();
      void server.close();
    });
    server
      .connect(transport)
      .then(() => transport.handleRequest(req, res))
      .catch((error: unknown) => {
        if (!res.headersSent) refuse(res, 500, errorMessage(error));
      });
  });
  await new Promise<void>((resolve, reject) => {
    http.once('error', reject);
    http.listen(options.port ?? 3333, host, () => resolve());
  });
  const port = (http.address() as AddressInfo).port;
  const shown = host.includes(':') ? `[${host}]` : host;
  return {
    url: `http://${shown}:${port}${settings.path}`,
    port,
    close: async () => {
      await sessions?.closeAll();
      await new Promise<void>((resolve) => {
        http.closeAllConnections();
        http.close(() => resolve());
      });
    },
  };
}
