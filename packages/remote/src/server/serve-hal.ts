// Serves one HAL over WebSocket. Calls run the moment they arrive (never queued behind each
// other), so an e-stop or a stop is never delayed by a long motion; one client controls, the
// others watch. See docs/remote.md.
import type { Server } from 'node:http';
import type { AddressInfo } from 'node:net';
import { ControllerWatch, ServedCalls } from '@hal/runtime';
import { scoped, silentLogger } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { WebSocketServer } from 'ws';
import type { ClientSession } from './client-session.js';
import type { HalServer, ServeHalOptions } from './options.js';
import { serveSettings } from './serve-settings.js';
import type { ServerState } from './server-state.js';
import { sessionOutput } from './session-output.js';
import { streamStates } from './state-stream.js';
import { openDoor } from './ws-door.js';

const NS = 'hal:remote:server';

/** Serves `hal` over WebSocket. Resolves once listening; rejects if the options are unsafe. */
export async function serveHal(
  hal: HardwareAbstractionLayer,
  options: ServeHalOptions = {},
): Promise<HalServer> {
  const settings = serveSettings(options);
  const state = serverState(hal, options, settings);
  const { http, wss } = openDoor(state);
  const stream = streamStates(state);
  await listen(http, settings.port, settings.host);
  const bound = http.address() as AddressInfo;
  const urlHost = settings.host.includes(':') ? `[${settings.host}]` : settings.host;
  state.log('info', `serving ${hal.mode} HAL on ws://${urlHost}:${bound.port}`);

  let closed: Promise<void> | undefined;
  return {
    url: `ws://${urlHost}:${bound.port}`,
    address: { host: settings.host, port: bound.port },
    clientCount: () => state.sessions.size,
    close: () => {
      closed ??= closeServer(state, stream, http, wss);
      return closed;
    },
  };
}

/** The shared state of a new server: no client yet, every call run the moment it arrives. */
function serverState(
  hal: HardwareAbstractionLayer,
  options: ServeHalOptions,
  settings: ServerState['settings'],
): ServerState {
  const scopedLog = scoped(options.logger ?? silentLogger, NS);
  // A silent client is dropped, and the robot stopped if it was the controller.
  const controllers: ControllerWatch = new ControllerWatch(hal, {
    timeoutMs: settings.heartbeatTimeoutMs,
    log: scopedLog,
    onSilent: (id, silentMs) => {
      const session = [...state.sessions.values()].find((s) => s.id === id);
      if (session === undefined) return;
      state.release(session, `silent for ${silentMs} ms`);
      session.socket.terminate();
    },
  });
  const state: ServerState = {
    hal,
    settings,
    deviceId: options.deviceId,
    // every call runs the moment it arrives: the HAL orders its own motions, and a stop or an
    // e-stop never waits behind one
    served: new ServedCalls(hal, { calls: options.calls, order: 'concurrent' }),
    sessions: new Map(),
    controller: undefined,
    controllers,
    out: sessionOutput(hal, options.deviceId),
    log: (level, message, fields) => scopedLog[level](message, fields),
    release: (session: ClientSession, why: string) => {
      state.sessions.delete(session.socket);
      controllers.forget(session.id);
      if (state.controller === session) {
        state.controller = undefined;
        void controllers.stopFor(session.id, why);
      }
    },
  };
  return state;
}

/** Starts `http` listening; rejects with its error (a port in use) if it cannot. */
async function listen(http: Server, port: number, host: string): Promise<void> {
  await new Promise<void>((resolve, reject) => {
    http.once('error', reject);
    http.listen(port, host, () => {
      http.off('error', reject);
      resolve();
    });
  });
}

/** Releases and closes every client (stopping the controller's robot), then stops listening. */
async function closeServer(
  state: ServerState,
  stream: ReturnType<typeof setInterval>,
  http: Server,
  wss: WebSocketServer,
): Promise<void> {
  state.controllers.close();
  clearInterval(stream);
  for (const session of [...state.sessions.values()]) {
    state.release(session, 'server closing');
    session.socket.close(1001, 'server closing');
  }
  await new Promise<void>((resolve) => wss.close(() => resolve()));
  for (const ws of wss.clients) ws.terminate();
  await new Promise<void>((resolve) => {
    http.close(() => resolve());
    http.closeAllConnections();
  });
}
