// Serves one HAL over WebSocket. Calls run the moment they arrive (never queued behind each
// other), so an e-stop or a stop is never delayed by a long motion; one client controls, the
// others watch. See docs/remote.md.
import { randomUUID } from 'node:crypto';
import { createServer } from 'node:http';
import type { IncomingMessage } from 'node:http';
import type { AddressInfo } from 'node:net';
import {
  ControllerWatch,
  HalError,
  ServedCalls,
  scoped,
  silentLogger,
  toHalError,
  trustedOrigin,
} from '@hal/types';
import type { HalErrorCode, HardwareAbstractionLayer, LogLevel } from '@hal/types';
import { WebSocketServer } from 'ws';
import type { RawData, WebSocket } from 'ws';
import {
  MESSAGE_SCHEMAS,
  decodeArgs,
  decodeMessage,
  encodeMessage,
  readRequestId,
} from '../protocol.js';
import type { MessageSchema, Role } from '../protocol.js';
import { checkBinding, doorRefusal, refuseUpgrade } from './auth.js';
import type { ClientSession } from './client-session.js';
import { SERVE_DEFAULTS } from './options.js';
import type { HalServer, ServeHalOptions } from './options.js';

const NS = 'hal:remote:server';
// ws closes the socket above this; below it, an oversized message only gets an error reply.
const HARD_LIMIT_FACTOR = 4;

/** Serves `hal` over WebSocket. Resolves once listening; rejects if the options are unsafe. */
export async function serveHal(
  hal: HardwareAbstractionLayer,
  options: ServeHalOptions = {},
): Promise<HalServer> {
  const host = options.host ?? SERVE_DEFAULTS.host;
  // an empty token is none, as checkBinding reads it
  const token = options.token === '' ? undefined : options.token;
  checkBinding(host, token);
  const allowedOrigins = new Set((options.allowedOrigins ?? []).map((o) => trustedOrigin(o)));
  const heartbeatTimeoutMs = options.heartbeatTimeoutMs ?? SERVE_DEFAULTS.heartbeatTimeoutMs;
  if (!(heartbeatTimeoutMs >= 100 && heartbeatTimeoutMs <= 10_000)) {
    throw new HalError('RANGE_EXCEEDED', '"heartbeatTimeoutMs" must be 100..10000 ms', {
      details: { parameter: 'heartbeatTimeoutMs', received: heartbeatTimeoutMs },
    });
  }
  const stateRateHz = options.stateRateHz ?? SERVE_DEFAULTS.stateRateHz;
  const maxMessageBytes = options.maxMessageBytes ?? SERVE_DEFAULTS.maxMessageBytes;
  const scopedLog = scoped(options.logger ?? silentLogger, NS);
  const log = (level: LogLevel, message: string, fields?: Record<string, unknown>) =>
    scopedLog[level](message, fields);
  const sender = () => ({
    deviceId: options.deviceId ?? hal.getDeviceInfo().id,
    caps: hal.getDeviceInfo().capabilities,
  });

  // every call runs the moment it arrives: the HAL orders its own motions, and a stop or an
  // e-stop never waits behind one
  const served = new ServedCalls(hal, { calls: options.calls, order: 'concurrent' });
  const sessions = new Map<WebSocket, ClientSession>();
  let controller: ClientSession | undefined;

  const send = <K extends MessageSchema>(
    session: ClientSession,
    schema: K,
    payload: Parameters<typeof encodeMessage<K>>[2],
  ) => {
    if (session.socket.readyState !== session.socket.OPEN) return;
    session.socket.send(encodeMessage(schema, sender(), payload));
  };
  const reply = (session: ClientSession, id: string | null, outcome: unknown, error?: HalError) => {
    const safety = hal.safety.getSafetyStatus();
    if (error === undefined) {
      send(session, MESSAGE_SCHEMAS.reply, { id, ok: true, value: outcome ?? null, safety });
    } else {
      const shape: { code: string; message: string; details?: Record<string, unknown> } = {
        code: error.code,
        message: error.message,
      };
      if (error.details !== undefined) shape.details = error.details;
      send(session, MESSAGE_SCHEMAS.reply, { id, ok: false, error: shape, safety });
    }
  };
  const setRole = (session: ClientSession, role: Role, reason: string) => {
    session.role = role;
    send(session, MESSAGE_SCHEMAS.control, { role, reason });
  };

  // A silent client is dropped, and the robot stopped if it was the controller.
  const controllers: ControllerWatch = new ControllerWatch(hal, {
    timeoutMs: heartbeatTimeoutMs,
    log: scopedLog,
    onSilent: (id, silentMs) => {
      const session = [...sessions.values()].find((s) => s.id === id);
      if (session === undefined) return;
      release(session, `silent for ${silentMs} ms`);
      session.socket.terminate();
    },
  });

  const release = (session: ClientSession, why: string) => {
    sessions.delete(session.socket);
    controllers.forget(session.id);
    if (controller === session) {
      controller = undefined;
      void controllers.stopFor(session.id, why);
    }
  };

  const runCall = (session: ClientSession, id: string, call: string, rawArgs: unknown[]) => {
    const spec = served.find(call);
    if (spec === undefined) {
      reply(session, id, null, errorOf('UNKNOWN_COMMAND', `unknown call "${call}"`, { call }));
      return;
    }
    const hint = 'send hal.remote.take_control first';
    const refusal = served.refusal(spec, session.role === 'controller', hint);
    if (refusal !== undefined) {
      reply(session, id, null, refusal);
      return;
    }
    const motion = spec.kind === 'motion';
    if (motion) session.running += 1;
    served
      .run(spec, decodeArgs(rawArgs))
      .then(
        (value) => reply(session, id, value),
        (e: unknown) => reply(session, id, null, toHalError(e)),
      )
      .finally(() => {
        if (motion) session.running -= 1;
      });
  };

  const onMessage = (session: ClientSession, data: RawData, isBinary: boolean) => {
    controllers.heard(session.id);
    const size = Array.isArray(data)
      ? data.reduce((n, b) => n + b.length, 0)
      : data instanceof ArrayBuffer
        ? data.byteLength
        : data.length;
    const text = isBinary ? '' : Buffer.isBuffer(data) ? data.toString('utf8') : String(data);
    if (size > maxMessageBytes) {
      reply(
        session,
        readRequestId(text),
        null,
        errorOf('MALFORMED', `message of ${size} bytes is over the ${maxMessageBytes}-byte limit`),
      );
      return;
    }
    if (isBinary) {
      reply(session, null, null, errorOf('MALFORMED', 'binary messages are not accepted'));
      return;
    }
    let message: ReturnType<typeof decodeMessage>;
    try {
      message = decodeMessage(text);
    } catch (e) {
      reply(session, readRequestId(text), null, toHalError(e));
      return;
    }
    switch (message.schema) {
      case MESSAGE_SCHEMAS.call: {
        const { id, call, args } = message.envelope.payload;
        runCall(session, id, call, args);
        return;
      }
      case MESSAGE_SCHEMAS.heartbeat:
        return;
      case MESSAGE_SCHEMAS.subscribe:
        session.subscribed = message.envelope.payload.state;
        return;
      case MESSAGE_SCHEMAS.takeControl: {
        const previous = controller;
        if (previous !== session) {
          controller = session;
          if (previous !== undefined) {
            setRole(previous, 'watcher', `control taken by client ${session.id}`);
          }
          log('info', `client ${session.id} took control`, { previous: previous?.id });
        }
        setRole(session, 'controller', 'control taken');
        reply(session, message.envelope.payload.id ?? null, { role: 'controller' });
        return;
      }
      default:
        reply(
          session,
          null,
          null,
          errorOf('MALFORMED', `"${message.schema}" is not a message a client sends`),
        );
    }
  };

  const http = createServer((_req, res) => {
    res.writeHead(426, { 'content-type': 'text/plain' }).end('WebSocket only\n');
  });
  const wss = new WebSocketServer({
    noServer: true,
    maxPayload: maxMessageBytes * HARD_LIMIT_FACTOR,
  });
  http.on('upgrade', (request, socket, head) => {
    const refused = doorRefusal(request, token, allowedOrigins);
    if (refused !== undefined) {
      log('warn', `refused a connection (HTTP ${refused.status}): ${refused.reason}`, {
        from: request.socket.remoteAddress,
      });
      refuseUpgrade(socket, refused);
      return;
    }
    wss.handleUpgrade(request, socket, head, (ws) => wss.emit('connection', ws, request));
  });
  wss.on('connection', (socket: WebSocket, request: IncomingMessage) => {
    // `?role=watch`: a client that only watches never gets control by arriving first.
    const watchOnly =
      new URL(request.url ?? '/', 'http://localhost').searchParams.get('role') === 'watch';
    const session: ClientSession = {
      id: randomUUID().slice(0, 8),
      socket,
      role: controller === undefined && !watchOnly ? 'controller' : 'watcher',
      subscribed: false,
      running: 0,
    };
    if (session.role === 'controller') controller = session;
    sessions.set(socket, session);
    controllers.watch(session.id);
    log('info', `client ${session.id} connected as ${session.role}`);
    const info = hal.getDeviceInfo();
    send(session, MESSAGE_SCHEMAS.hello, {
      session_id: session.id,
      role: session.role,
      mode: hal.mode,
      // the id the server goes by (a physical robot's HAL knows no name of its own)
      device: { ...info, id: options.deviceId ?? info.id },
      heartbeat_timeout_ms: heartbeatTimeoutMs,
      state_rate_hz: stateRateHz,
      max_message_bytes: maxMessageBytes,
    });
    socket.on('message', (data, isBinary) => onMessage(session, data, isBinary));
    socket.on('close', () => release(session, 'disconnected'));
    socket.on('error', (e) =>
      log('warn', `client ${session.id} socket error`, { error: e.message }),
    );
  });

  let streaming = false;
  const stream = setInterval(() => {
    if (streaming) return;
    const subscribers = [...sessions.values()].filter((s) => s.subscribed);
    if (subscribers.length === 0) return;
    streaming = true;
    hal.locomotion
      .getPose()
      .then(
        (pose) => pose,
        () => null,
      )
      .then((pose) => {
        const safety = hal.safety.getSafetyStatus();
        const moving = [...sessions.values()].some((s) => s.running > 0);
        for (const session of subscribers) {
          // A client that cannot keep up skips states rather than growing a backlog.
          if (session.socket.bufferedAmount > maxMessageBytes) continue;
          send(session, MESSAGE_SCHEMAS.state, { pose, moving, safety, role: session.role });
        }
      })
      .finally(() => {
        streaming = false;
      });
  }, 1000 / stateRateHz);

  await new Promise<void>((resolve, reject) => {
    http.once('error', reject);
    http.listen(options.port ?? SERVE_DEFAULTS.port, host, () => {
      http.off('error', reject);
      resolve();
    });
  });
  const bound = http.address() as AddressInfo;
  const address = { host, port: bound.port };
  const urlHost = host.includes(':') ? `[${host}]` : host;
  log('info', `serving ${hal.mode} HAL on ws://${urlHost}:${bound.port}`);

  let closed: Promise<void> | undefined;
  return {
    url: `ws://${urlHost}:${bound.port}`,
    address,
    clientCount: () => sessions.size,
    close: () => {
      closed ??= (async () => {
        controllers.close();
        clearInterval(stream);
        for (const session of [...sessions.values()]) {
          release(session, 'server closing');
          session.socket.close(1001, 'server closing');
        }
        await new Promise<void>((resolve) => wss.close(() => resolve()));
        for (const ws of wss.clients) ws.terminate();
        await new Promise<void>((resolve) => {
          http.close(() => resolve());
          http.closeAllConnections();
        });
      })();
      return closed;
    },
  };
}

function errorOf(code: HalErrorCode, message: string, details?: Record<string, unknown>): HalError {
  return new HalError(code, message, details === undefined ? {} : { details });
}
