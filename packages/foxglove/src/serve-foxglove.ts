// Serves a live view of one HAL over the Foxglove WebSocket protocol (`foxglove.websocket.v1`),
// for Foxglove and Lichtblick: the recorder's topics and schemas, teleop and stop services. See
// docs/live.md.
import { createServer } from 'node:http';
import type { IncomingMessage } from 'node:http';
import type { AddressInfo } from 'node:net';
import { FoxgloveServer, ServerCapability } from './ws-protocol.js';
import type { ServiceCallRequest } from '@foxglove/ws-protocol';
import { checkBinding, refuseUpgrade } from '@hal/remote/server';
import { createToolExecutor, robotConfigOf, toolBackedHal } from '@hal/tools';
import { trustedOrigin } from '@hal/runtime';
import { HalError, scoped, silentLogger, withTimeout } from '@hal/types';
import type { HardwareAbstractionLayer, LogLevel } from '@hal/types';
import { WebSocketServer } from 'ws';
import type { WebSocket } from 'ws';
import { foxgloveDoorRefusal } from './door.js';
import { FOXGLOVE_DEFAULTS } from './options.js';
import type {
  FoxgloveLiveServer,
  FoxgloveServeOptions,
  FoxgloveStats,
  ViewerDrops,
} from './options.js';
import { livePerception } from './perception.js';
import { LivePublisher } from './publisher.js';
import { controlServices } from './services.js';
import { acceptTeleop } from './teleop-channel.js';
import { tapHal } from './tap.js';
import { liveNames } from './topics.js';
import { ViewerSocket } from './viewer-socket.js';

const NS = 'hal:foxglove';
/** How long a viewer has to answer the server's close before it is cut off, ms. */
const CLOSE_GRACE_MS = 500;
/** Viewers gone whose drops stats() still lists, at most (the total counts them all). */
const MAX_GONE = 100;

interface Viewer {
  name: string;
  socket: ViewerSocket;
}

function rate(name: string, value: number, min: number, max: number): number {
  if (!(value >= min && value <= max)) {
    throw new HalError('RANGE_EXCEEDED', `"${name}" must be ${min}..${max}`, {
      details: { parameter: name, received: value },
    });
  }
  return value;
}

/**
 * Serves a live view of `hal` for Foxglove or Lichtblick. Resolves once listening; rejects with
 * INVALID_PARAMETER if the options are unsafe (a non-loopback host without a token) and
 * RANGE_EXCEEDED for a rate out of range. Read the returned `hal` for calls the view should show.
 */
export async function serveFoxglove(
  hal: HardwareAbstractionLayer,
  options: FoxgloveServeOptions = {},
): Promise<FoxgloveLiveServer> {
  const host = options.host ?? FOXGLOVE_DEFAULTS.host;
  const token = options.token === '' ? undefined : options.token;
  checkBinding(host, token);
  const allowedOrigins = new Set((options.allowedOrigins ?? []).map((o) => trustedOrigin(o)));
  const poseRateHz = rate('poseRateHz', options.poseRateHz ?? FOXGLOVE_DEFAULTS.poseRateHz, 1, 100);
  const cameraRateHz = rate(
    'cameraRateHz',
    options.cameraRateHz ?? FOXGLOVE_DEFAULTS.cameraRateHz,
    0,
    30,
  );
  const linkRateHz = rate('linkRateHz', options.linkRateHz ?? FOXGLOVE_DEFAULTS.linkRateHz, 0, 10);
  const holdMs = rate(
    'teleopHoldMs',
    options.teleopHoldMs ?? FOXGLOVE_DEFAULTS.teleopHoldMs,
    100,
    2000,
  );
  const maxQueuedBytes = rate(
    'maxQueuedBytes',
    options.maxQueuedBytes ?? FOXGLOVE_DEFAULTS.maxQueuedBytes,
    1024,
    256 * 1024 * 1024,
  );
  const scopedLog = scoped(options.logger ?? silentLogger, NS);
  const names = liveNames(options.namespace);
  const deviceId = options.deviceId ?? hal.getDeviceInfo().id;

  const protocol = new FoxgloveServer({
    name: `hal ${deviceId}`,
    capabilities: [ServerCapability.clientPublish, ServerCapability.services],
    supportedEncodings: ['json'],
    metadata: { device_id: deviceId, mode: String(hal.mode) },
  });
  const publisher = new LivePublisher(protocol, hal, names, {
    poseRateHz,
    cameraRateHz,
    linkRateHz,
    deviceId,
  });
  // what the server says goes to its logger and, for the viewers, to the log topic
  const log = (level: LogLevel, message: string, fields?: Record<string, unknown>) => {
    scopedLog[level](message, fields);
    publisher.log(message, level, NS);
  };
  protocol.on('error', (error) =>
    log('warn', `a viewer sent what could not be read: ${error.message}`),
  );

  // calls through the view itself show in it as others' do
  const tapped = tapHal(hal, {
    log: (message, level) => publisher.log(String(message), level, deviceId),
    safety: (event, result, reason) => publisher.safetyCall(event, result, reason),
    frame: (dataUrl) => publisher.frame(dataUrl),
  });

  // teleop and the reset go through the leash; stop and the e-stop never do
  const leashed = toolBackedHal(
    tapped,
    createToolExecutor(tapped, { leash: options.leash ?? {} }).execute,
  );
  const teleop = acceptTeleop(protocol, {
    topic: names.control.teleop,
    leashed,
    robot: hal,
    config: robotConfigOf(hal),
    holdMs,
    log,
  });
  const viewers = new Map<WebSocket, Viewer>();
  const gone: ViewerDrops[] = [];
  let droppedByGone = 0;
  let nextViewer = 1;

  const services = controlServices(protocol, tapped, leashed, names.control, log);
  protocol.on('serviceCallRequest', (request: ServiceCallRequest, connection) => {
    services.call(request, connection);
  });

  const http = createServer((_req, res) => {
    res.writeHead(426, { 'content-type': 'text/plain' }).end('Foxglove WebSocket only\n');
  });
  const wss = new WebSocketServer({
    noServer: true,
    handleProtocols: (protocols) => protocol.handleProtocols(protocols),
  });
  http.on('upgrade', (request, socket, head) => {
    const refused = foxgloveDoorRefusal(request, token, allowedOrigins);
    if (refused !== undefined) {
      log('warn', `refused a viewer (HTTP ${refused.status}): ${refused.reason}`, {
        from: request.socket.remoteAddress,
        origin: request.headers.origin,
      });
      refuseUpgrade(socket, refused);
      return;
    }
    wss.handleUpgrade(request, socket, head, (ws) => wss.emit('connection', ws, request));
  });
  wss.on('connection', (ws: WebSocket, request: IncomingMessage) => {
    const name = `viewer-${nextViewer++}`;
    const socket = new ViewerSocket(ws, maxQueuedBytes, (id) => publisher.topicOf(id), {
      firstDrop: (topic) =>
        log('warn', `${name} cannot keep up: dropping its messages on ${topic} (counted)`),
    });
    const viewer: Viewer = { name, socket };
    viewers.set(ws, viewer);
    // `?role=watch`: a viewer that only watches (and stops), as on hal serve's WebSocket door
    const role = new URL(request.url ?? '/', 'http://localhost').searchParams.get('role');
    teleop.joined(socket, name, role === 'watch');
    ws.on('close', () => {
      viewers.delete(ws);
      const drops = dropsOf(viewer);
      if (drops.dropped > 0) {
        droppedByGone += drops.dropped;
        gone.push(drops);
        // the latest ones only: a server up for weeks keeps no list that grows with it
        if (gone.length > MAX_GONE) gone.shift();
        log('info', `${name} left; ${drops.dropped} messages were dropped for it`, drops.byTopic);
      }
      teleop.left(socket);
    });
    ws.on('error', (e) => log('warn', `${name} socket error: ${e.message}`));
    protocol.handleConnection(socket, name);
    log('info', `${name} connected`);
  });

  await new Promise<void>((resolve, reject) => {
    http.once('error', reject);
    http.listen(options.port ?? FOXGLOVE_DEFAULTS.port, host, () => {
      http.off('error', reject);
      resolve();
    });
  });
  const bound = http.address() as AddressInfo;
  const urlHost = host.includes(':') ? `[${host}]` : host;
  const url = `ws://${urlHost}:${bound.port}`;
  publisher.start();
  const perception =
    options.perception === undefined
      ? undefined
      : livePerception(publisher, options.perception, options.namespace);
  log('info', `live view of ${deviceId} on ${url} (foxglove.websocket.v1)`);

  let closed: Promise<void> | undefined;
  return {
    url,
    address: { host, port: bound.port },
    hal: tapped,
    stats: (): FoxgloveStats => {
      const current = [...viewers.values()].map(dropsOf);
      const drops = [...current, ...gone];
      const droppedNow = current.reduce((n, d) => n + d.dropped, 0);
      const sent: Record<string, number> = {};
      for (const v of viewers.values()) {
        for (const [topic, n] of v.socket.counts.sent) sent[topic] = (sent[topic] ?? 0) + n;
      }
      return {
        clients: viewers.size,
        sent,
        dropped: droppedNow + droppedByGone,
        drops,
        teleop: teleop.counts(),
      };
    },
    close: () => {
      closed ??= (async () => {
        publisher.stop();
        perception?.stop();
        const open = [...viewers.keys()];
        for (const ws of open) ws.close(1001, 'server closing');
        // a viewer that does not answer the close (a stalled one) is cut off after a moment
        await withTimeout(
          Promise.all(open.map((ws) => new Promise((resolve) => ws.once('close', resolve)))),
          CLOSE_GRACE_MS,
        );
        for (const ws of wss.clients) ws.terminate();
        await new Promise<void>((resolve) => wss.close(() => resolve()));
        await new Promise<void>((resolve) => {
          http.close(() => resolve());
          http.closeAllConnections();
        });
      })();
      return closed;
    },
  };
}

function dropsOf(viewer: Viewer): ViewerDrops {
  const byTopic = Object.fromEntries(viewer.socket.counts.dropped);
  return {
    client: viewer.name,
    dropped: Object.values(byTopic).reduce((n, d) => n + d, 0),
    byTopic,
  };
}
