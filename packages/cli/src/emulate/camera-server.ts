// The ESP32-CAM's HTTP interface (firmware/esp32-cam-mjpeg/), served on this computer with frames
// from any source: GET /stream (multipart/x-mixed-replace JPEG, one frame every 100 ms), GET
// /status (JSON), GET / (a page showing the stream). With a token, /stream and /status need it
// (`?token=` or `Authorization: Bearer`), compared in constant time; the status codes, bodies and
// headers are the sketch's (src/cam_http.cpp): 401 with the Bearer challenge, 404, 405 for a method
// other than GET (no CORS origin is configured, so OPTIONS too), 408 for a head slower than 2 s,
// 431 for one over 1024 bytes, 503 beyond two streams.
import { createServer } from 'node:http';
import type { IncomingMessage, Server, ServerResponse } from 'node:http';
import type { Socket } from 'node:net';

/** The sketch's limits (firmware/esp32-cam-mjpeg/src/cam_http.h and the .ino). */
export const CAMERA_LIMITS = {
  frameIntervalMs: 100,
  maxStreams: 2,
  maxRequestHead: 1024,
  requestTimeoutMs: 2000,
  width: 320,
  height: 240,
} as const;

/** The multipart boundary of the stream, as the sketch names it. */
export const STREAM_BOUNDARY = 'cubeframe';

/** Options of {@link startCameraServer}. */
export interface CameraServerOptions {
  /** Address to listen on. */
  host: string;
  /** Port; 0 picks a free one. */
  port: number;
  /** The camera's token (its CAM_TOKEN); none lets every client in. */
  token?: string;
  /** The next JPEG to send; a failure skips a beat (20 ms) as a missing frame buffer does. */
  frame: () => Promise<Uint8Array>;
  /** Time between the frames of one stream, ms. Default 100 (10 fps). */
  frameIntervalMs?: number;
  /** Streams at once; more get 503. Default 2. */
  maxStreams?: number;
  /** The clock, ms. Default `performance.now`. */
  now?: () => number;
}

/** What GET /status answers. */
export interface CameraStatus {
  fps: number;
  frames_served: number;
  uptime_ms: number;
  /** No radio here: always 0. */
  rssi_dbm: number;
  stream_clients: number;
  width: number;
  height: number;
}

/** A running camera server. */
export interface CameraServer {
  readonly host: string;
  readonly port: number;
  /** What GET /status would answer now. */
  status(): CameraStatus;
  /** Ends every stream and closes the port. */
  close(): Promise<void>;
}

const INDEX_PAGE =
  '<!doctype html><title>cube camera</title>' +
  '<img id="s" width="320" height="240" alt="camera">' +
  "<script>document.getElementById('s').src='/stream'+location.search</script>";

/** The sketch's ConstantTimeEquals: the time depends only on the expected token's length. */
function constantTimeEquals(expected: string, given: string): boolean {
  let diff = expected.length === given.length ? 0 : 1;
  for (let i = 0; i < expected.length; i += 1) {
    diff |= expected.charCodeAt(i) ^ (i < given.length ? given.charCodeAt(i) : 0);
  }
  return diff === 0;
}

/** The Bearer token of an Authorization header, as the sketch reads it. */
function bearerOf(header: string | undefined): string | undefined {
  const match = /^bearer +(.*?)[ \t]*$/i.exec(header?.trimStart() ?? '');
  return match?.[1];
}

function authorized(token: string | undefined, query: URLSearchParams, req: IncomingMessage) {
  if (token === undefined || token === '') return true;
  const fromQuery = query.get('token');
  const fromHeader = bearerOf(req.headers.authorization);
  // both are always compared, so the time says nothing either
  const queryOk = fromQuery !== null && constantTimeEquals(token, fromQuery);
  const bearerOk = fromHeader !== undefined && constantTimeEquals(token, fromHeader);
  return queryOk || bearerOk;
}

function fixed(
  res: ServerResponse,
  status: number,
  body: string,
  headers: Record<string, string> = {},
) {
  res.writeHead(status, {
    'Content-Type': status === 200 ? 'text/html' : 'text/plain',
    'Content-Length': String(Buffer.byteLength(body)),
    ...headers,
    Connection: 'close',
  });
  res.end(body);
}

/** Frames served per second over windows of at least a second, as the sketch's UpdateFps. */
class FpsWindow {
  #start: number;
  #frames = 0;
  fps = 0;
  constructor(now: number) {
    this.#start = now;
  }
  count(): void {
    this.#frames += 1;
  }
  update(now: number): void {
    const span = now - this.#start;
    if (span < 1000) return;
    this.fps = Math.round(((this.#frames * 1000) / span) * 10) / 10;
    this.#frames = 0;
    this.#start = now;
  }
}

/**
 * Serves the ESP32-CAM's interface on `host:port`. Rejects with the system's error when the port
 * cannot be bound.
 */
export async function startCameraServer(options: CameraServerOptions): Promise<CameraServer> {
  const now = options.now ?? (() => performance.now());
  const interval = options.frameIntervalMs ?? CAMERA_LIMITS.frameIntervalMs;
  const maxStreams = options.maxStreams ?? CAMERA_LIMITS.maxStreams;
  const started = now();
  const fps = new FpsWindow(started);
  const sockets = new Set<Socket>();
  let streams = 0;
  let served = 0;
  let closing = false;

  const status = (): CameraStatus => {
    fps.update(now());
    return {
      fps: fps.fps,
      frames_served: served,
      uptime_ms: Math.floor(now() - started),
      rssi_dbm: 0,
      stream_clients: streams,
      width: CAMERA_LIMITS.width,
      height: CAMERA_LIMITS.height,
    };
  };

  const stream = async (res: ServerResponse): Promise<void> => {
    streams += 1;
    let open = true;
    let wake: () => void = () => undefined;
    res.once('close', () => {
      open = false;
      wake();
    });
    const sleep = (ms: number) =>
      new Promise<void>((resolve) => {
        const timer = setTimeout(resolve, ms);
        wake = () => {
          clearTimeout(timer);
          resolve();
        };
      });
    try {
      res.setHeader('Content-Type', `multipart/x-mixed-replace; boundary=${STREAM_BOUNDARY}`);
      res.setHeader('Cache-Control', 'no-cache');
      res.setHeader('Connection', 'close');
      // the sketch writes the parts as they are, with no chunked encoding
      res.removeHeader('Transfer-Encoding');
      res.writeHead(200);
      let due = now();
      while (open && !closing) {
        let jpeg: Uint8Array;
        try {
          jpeg = await options.frame();
        } catch {
          await sleep(20);
          continue;
        }
        if (!open || closing) break;
        res.write(
          `--${STREAM_BOUNDARY}\r\nContent-Type: image/jpeg\r\nContent-Length: ${jpeg.length}\r\n\r\n`,
        );
        res.write(jpeg);
        const flushed = res.write('\r\n');
        served += 1;
        fps.count();
        fps.update(now());
        if (!flushed) {
          // a slow reader: wait for its buffer to drain (or for it to go)
          await new Promise<void>((resolve) => {
            wake = resolve;
            res.once('drain', resolve);
          });
        }
        due += interval;
        const wait = due - now();
        if (wait > 0) await sleep(wait);
        else due = now(); // behind: no burst to catch up, as vTaskDelayUntil
      }
    } finally {
      streams -= 1;
      res.end();
    }
  };

  const handle = (req: IncomingMessage, res: ServerResponse): void => {
    res.sendDate = false; // the camera has no clock to date its answers with
    const url = new URL(req.url ?? '/', 'http://camera');
    if (req.method !== 'GET') {
      fixed(res, 405, 'only GET\n');
      return;
    }
    if (url.pathname === '/') {
      fixed(res, 200, INDEX_PAGE);
      return;
    }
    if (url.pathname !== '/status' && url.pathname !== '/stream') {
      fixed(res, 404, 'not found\n');
      return;
    }
    if (!authorized(options.token, url.searchParams, req)) {
      fixed(res, 401, 'a token is required: ?token= or Authorization: Bearer\n', {
        'WWW-Authenticate': 'Bearer realm="cube-camera"',
      });
      return;
    }
    if (url.pathname === '/status') {
      const body = JSON.stringify(status());
      res.writeHead(200, {
        'Content-Type': 'application/json',
        'Content-Length': String(Buffer.byteLength(body)),
        'Cache-Control': 'no-cache',
        Connection: 'close',
      });
      res.end(body);
      return;
    }
    if (streams >= maxStreams) {
      fixed(res, 503, 'busy, try again\n');
      return;
    }
    void stream(res);
  };

  const server: Server = createServer(
    {
      maxHeaderSize: CAMERA_LIMITS.maxRequestHead,
      // a stream is one long response: only the head has a time limit
      requestTimeout: 0,
      connectionsCheckingInterval: 250,
    },
    handle,
  );
  server.headersTimeout = CAMERA_LIMITS.requestTimeoutMs;
  server.keepAliveTimeout = 0;
  server.on('connection', (socket: Socket) => {
    sockets.add(socket);
    socket.once('close', () => sockets.delete(socket));
  });
  await new Promise<void>((resolve, reject) => {
    server.once('error', reject);
    server.listen(options.port, options.host, () => {
      server.off('error', reject);
      resolve();
    });
  });
  const address = server.address();
  const port = typeof address === 'object' && address !== null ? address.port : options.port;
  return {
    host: options.host,
    port,
    status,
    close: async () => {
      closing = true;
      const closed = new Promise<void>((resolve) => server.close(() => resolve()));
      for (const socket of sockets) socket.destroy();
      await closed;
    },
  };
}
