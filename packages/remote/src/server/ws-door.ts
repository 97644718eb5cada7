import { randomUUID } from 'node:crypto';
import { createServer } from 'node:http';
import type { IncomingMessage, Server } from 'node:http';
import { WebSocketServer } from 'ws';
import type { WebSocket } from 'ws';
import { MESSAGE_SCHEMAS } from '../protocol.js';
import { doorRefusal, refuseUpgrade } from './auth.js';
import { onClientMessage } from './client-messages.js';
import type { ClientSession } from './client-session.js';
import type { ServerState } from './server-state.js';

// ws closes the socket above this; below it, an oversized message only gets an error reply.
const HARD_LIMIT_FACTOR = 4;

/**
 * The HTTP server a remote HAL listens on (not yet listening) and its WebSocket server: plain
 * HTTP is answered 426, an upgrade that fails the door check (token, origin, host) is refused,
 * and every connection admitted becomes a client session.
 */
export function openDoor(state: ServerState): { http: Server; wss: WebSocketServer } {
  const { settings, log } = state;
  const http = createServer((_req, res) => {
    res.writeHead(426, { 'content-type': 'text/plain' }).end('WebSocket only\n');
  });
  const wss = new WebSocketServer({
    noServer: true,
    maxPayload: settings.maxMessageBytes * HARD_LIMIT_FACTOR,
  });
  http.on('upgrade', (request, socket, head) => {
    const refused = doorRefusal(request, settings.token, settings.allowedOrigins);
    if (refused !== undefined) {
      log('warn', `refused a connection (HTTP ${refused.status}): ${refused.reason}`, {
        from: request.socket.remoteAddress,
      });
      refuseUpgrade(socket, refused);
      return;
    }
    wss.handleUpgrade(request, socket, head, (ws) => wss.emit('connection', ws, request));
  });
  wss.on('connection', (socket: WebSocket, request: IncomingMessage) =>
    admit(state, socket, request),
  );
  return { http, wss };
}

/**
 * Opens a session for a new client: the controller if nobody controls and it did not ask only
 * to watch (`?role=watch`), else a watcher; greets it and listens to it.
 */
function admit(state: ServerState, socket: WebSocket, request: IncomingMessage): void {
  const { hal, settings, log } = state;
  // `?role=watch`: a client that only watches never gets control by arriving first.
  const watchOnly =
    new URL(request.url ?? '/', 'http://localhost').searchParams.get('role') === 'watch';
  const session: ClientSession = {
    id: randomUUID().slice(0, 8),
    socket,
    role: state.controller === undefined && !watchOnly ? 'controller' : 'watcher',
    subscribed: false,
    running: 0,
  };
  if (session.role === 'controller') state.controller = session;
  state.sessions.set(socket, session);
  state.controllers.watch(session.id);
  log('info', `client ${session.id} connected as ${session.role}`);
  const info = hal.getDeviceInfo();
  state.out.send(session, MESSAGE_SCHEMAS.hello, {
    session_id: session.id,
    role: session.role,
    mode: hal.mode,
    // the id the server goes by (a physical robot's HAL knows no name of its own)
    device: { ...info, id: state.deviceId ?? info.id },
    heartbeat_timeout_ms: settings.heartbeatTimeoutMs,
    state_rate_hz: settings.stateRateHz,
    max_message_bytes: settings.maxMessageBytes,
  });
  socket.on('message', (data, isBinary) => onClientMessage(state, session, data, isBinary));
  socket.on('close', () => state.release(session, 'disconnected'));
  socket.on('error', (e) => log('warn', `client ${session.id} socket error`, { error: e.message }));
}
