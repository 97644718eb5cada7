// Streamable HTTP with sessions: a client's `initialize` opens a session (a server of its own,
// named by the Mcp-Session-Id header the client then sends), and the server can talk to it
// between and during its requests: approval questions, progress, resource updates and log
// lines on the event streams of its POSTs and of its GET. DELETE ends a session.
import { randomUUID } from 'node:crypto';
import type { IncomingMessage, ServerResponse } from 'node:http';
import type { Server } from '@modelcontextprotocol/sdk/server/index.js';
import { StreamableHTTPServerTransport } from '@modelcontextprotocol/sdk/server/streamableHttp.js';

/** How many sessions may be open at once, by default; one more closes the least recently used. */
export const DEFAULT_MAX_SESSIONS = 16;

type Refuse = (res: ServerResponse, status: number, message: string) => void;

interface Session {
  transport: StreamableHTTPServerTransport;
  server: Server;
}

/** Closes a session's server (and so its transport); never throws. */
const end = (session: Session) => session.server.close().catch(() => undefined);

/**
 * The sessions of one endpoint: `handle` answers a request that passed the gate. A client that
 * goes away without ending its session leaves it open: when `maxSessions` are open, a new one
 * closes the session used least recently.
 */
export function httpSessions(create: () => Server, refuse: Refuse, maxSessions: number) {
  // in the order of their last use, the least recent first
  const sessions = new Map<string, Session>();

  async function open(req: IncomingMessage, res: ServerResponse): Promise<void> {
    const server = create();
    const transport = new StreamableHTTPServerTransport({
      sessionIdGenerator: () => randomUUID(),
      onsessioninitialized: (id) => {
        sessions.set(id, { transport, server });
      },
    });
    // set before connect: the server chains its own close after it
    transport.onclose = () => {
      if (transport.sessionId !== undefined) sessions.delete(transport.sessionId);
    };
    await server.connect(transport);
    await transport.handleRequest(req, res);
    // a first request that was no initialize opened nothing: drop its server
    if (transport.sessionId === undefined) await server.close();
  }

  return {
    async handle(req: IncomingMessage, res: ServerResponse): Promise<void> {
      const header = req.headers['mcp-session-id'];
      const id = Array.isArray(header) ? header[0] : header;
      if (id !== undefined) {
        const session = sessions.get(id);
        if (session === undefined) return refuse(res, 404, 'no such session: initialize again');
        sessions.delete(id);
        sessions.set(id, session); // used now: the most recent
        return session.transport.handleRequest(req, res);
      }
      if (req.method !== 'POST') {
        return refuse(res, 400, 'a session starts with an initialize request (POST)');
      }
      while (sessions.size >= maxSessions) {
        const [oldest, session] = sessions.entries().next().value as [string, Session];
        sessions.delete(oldest);
        await end(session);
      }
      return open(req, res);
    },
    /** Ends every session. */
    async closeAll(): Promise<void> {
      const all = [...sessions.values()];
      sessions.clear();
      await Promise.all(all.map(end));
    },
  };
}
