// captureFrame from an MJPEG stream served by a small local HTTP server, as the ESP32-CAM serves it.
import { createServer } from 'node:http';
import type { Server, ServerResponse } from 'node:http';
import type { AddressInfo } from 'node:net';
import { MjpegCamera, PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import { afterEach, describe, expect, it } from 'vitest';

const BOUNDARY = '123456789000000000000987654321';

/** A fake JPEG: SOI marker, a payload naming the frame, EOI marker. */
function jpeg(n: number): Buffer {
  return Buffer.concat([
    Buffer.from([0xff, 0xd8, 0xff, 0xe0]),
    Buffer.from(`frame-${n}`),
    Buffer.from([0xff, 0xd9]),
  ]);
}

const decodeDataUrl = (url: string) =>
  Buffer.from(url.replace(/^data:image\/jpeg;base64,/, ''), 'base64');

interface CameraServer {
  url: string;
  connections: number;
  /** Requests refused with 401 for a missing or wrong token. */
  refused: number;
  /** The Authorization headers the server saw, in order. */
  authorizations: Array<string | undefined>;
  /** Streams open now. */
  open: number;
  /** Sends frame n to every open stream, split into two writes. */
  send(n: number, options?: { withLength?: boolean }): void;
  /** Ends every open stream (the camera dropping the connection). */
  dropStreams(): void;
  close(): Promise<void>;
}

/** A camera server; with `token`, it answers 401 unless given `Authorization: Bearer {token}`. */
async function cameraServer(options: { token?: string } = {}): Promise<CameraServer> {
  const streams = new Set<ServerResponse>();
  let connections = 0;
  let refused = 0;
  const authorizations: Array<string | undefined> = [];
  const server: Server = createServer((request, response) => {
    if (request.url !== '/stream') {
      response.writeHead(404).end();
      return;
    }
    authorizations.push(request.headers.authorization);
    if (
      options.token !== undefined &&
      request.headers.authorization !== `Bearer ${options.token}`
    ) {
      refused += 1;
      response.writeHead(401, { 'WWW-Authenticate': 'Bearer realm="cube-camera"' }).end();
      return;
    }
    connections += 1;
    response.writeHead(200, {
      'Content-Type': `multipart/x-mixed-replace;boundary=${BOUNDARY}`,
      'Cache-Control': 'no-cache',
    });
    streams.add(response);
    response.on('close', () => streams.delete(response));
  });
  await new Promise<void>((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address() as AddressInfo;
  return {
    url: `http://127.0.0.1:${port}`,
    get connections() {
      return connections;
    },
    get refused() {
      return refused;
    },
    authorizations,
    get open() {
      return streams.size;
    },
    send: (n, options = {}) => {
      const body = jpeg(n);
      const length = options.withLength === false ? '' : `Content-Length: ${body.length}\r\n`;
      const part = Buffer.concat([
        Buffer.from(`\r\n--${BOUNDARY}\r\nContent-Type: image/jpeg\r\n${length}\r\n`),
        body,
      ]);
      for (const stream of streams) {
        stream.write(part.subarray(0, 20));
        stream.write(part.subarray(20));
      }
    },
    dropStreams: () => {
      for (const stream of streams) stream.destroy();
    },
    close: () =>
      new Promise<void>((resolve) => {
        for (const stream of streams) stream.destroy();
        server.close(() => resolve());
        // Node's fetch may keep an idle pooled socket after an abort (nodejs/undici#5845)
        server.closeAllConnections();
      }),
  };
}

describe('MjpegCamera', () => {
  const cleanups: Array<() => Promise<void>> = [];
  afterEach(async () => {
    for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
  });

  it('returns the first frame after the call, never one from before it, as a base64 JPEG data URL', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({ url: server.url, reconnectDelayMs: 20 });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    server.send(1);
    await expect.poll(() => camera.stats.frames, { timeout: 5000 }).toBe(1);
    // frame 1 is the latest, but it came before the call: the capture waits for frame 2
    let captured: string | undefined;
    const capture = camera.captureFrame().then((url) => (captured = url));
    await new Promise((resolve) => setTimeout(resolve, 50));
    expect(captured).toBeUndefined();
    server.send(2);
    await capture;
    expect(captured?.startsWith('data:image/jpeg;base64,')).toBe(true);
    expect(decodeDataUrl(captured ?? '')).toEqual(jpeg(2));
  });

  it('with maxFrameAgeMs, keeps the latest frame of the stream and returns it at once', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({
      url: server.url,
      reconnectDelayMs: 20,
      maxFrameAgeMs: 60_000,
    });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    server.send(1);
    server.send(2);
    server.send(3, { withLength: false });
    server.send(4);
    await expect.poll(() => camera.stats.frames, { timeout: 5000 }).toBe(4);
    const url = await camera.captureFrame();
    expect(url.startsWith('data:image/jpeg;base64,')).toBe(true);
    expect(decodeDataUrl(url)).toEqual(jpeg(4));
    expect(camera.stats.frames).toBe(4);
  });

  it('reconnects when the stream drops, and serves the frames that follow', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({
      url: server.url,
      reconnectDelayMs: 20,
      maxFrameAgeMs: 60_000,
    });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    server.send(1);
    await expect.poll(() => camera.stats.frames, { timeout: 5000 }).toBe(1);
    server.dropStreams();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(2);
    server.send(2);
    await expect
      .poll(async () => decodeDataUrl(await camera.captureFrame()), { timeout: 5000 })
      .toEqual(jpeg(2));
  });

  it('rejects with TIMEOUT when no frame comes', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({ url: server.url, frameTimeoutMs: 100 });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect(camera.captureFrame()).rejects.toMatchObject({ code: 'TIMEOUT' });
  });

  it('rejects captureFrame with NOT_READY before start() and after stop(), and opens no stream for it', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({ url: server.url, reconnectDelayMs: 20 });
    cleanups.push(() => camera.stop());
    await expect(camera.captureFrame()).rejects.toMatchObject({ code: 'NOT_READY' });
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    await camera.stop();
    await expect.poll(() => server.open, { timeout: 5000 }).toBe(0);
    await expect(camera.captureFrame()).rejects.toMatchObject({ code: 'NOT_READY' });
    await new Promise((resolve) => setTimeout(resolve, 100));
    expect(server.connections).toBe(1);
    expect(server.open).toBe(0);
    expect(camera.running).toBe(false);
  });

  it('stops at once while it waits to reconnect, leaving no timer behind', async () => {
    const server = await cameraServer();
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({ url: server.url, reconnectDelayMs: 600_000 });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    server.dropStreams();
    await expect.poll(() => server.open, { timeout: 5000 }).toBe(0);
    const started = performance.now();
    await camera.stop();
    // a generous bound: the reconnect delay is ten minutes, so this proves it was not waited out
    expect(performance.now() - started).toBeLessThan(5000);
    expect(server.connections).toBe(1);
  });
});

describe('MjpegCamera with a camera that requires a token', () => {
  const cleanups: Array<() => Promise<void>> = [];
  afterEach(async () => {
    for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
  });

  it('sends the configured token as a Bearer header and reads the stream', async () => {
    const server = await cameraServer({ token: 'cam-token_42' });
    cleanups.push(() => server.close());
    const camera = new MjpegCamera({
      url: server.url,
      token: 'cam-token_42',
      reconnectDelayMs: 20,
    });
    cleanups.push(() => camera.stop());
    camera.start();
    await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
    const capture = camera.captureFrame();
    server.send(5);
    expect(decodeDataUrl(await capture)).toEqual(jpeg(5));
    expect(server.refused).toBe(0);
    expect(server.authorizations).toEqual(['Bearer cam-token_42']);
  });

  it('is refused without the token or with a wrong one, and captureFrame says why', async () => {
    for (const token of [undefined, 'wrong-token']) {
      const server = await cameraServer({ token: 'cam-token_42' });
      cleanups.push(() => server.close());
      const camera = new MjpegCamera({
        url: server.url,
        reconnectDelayMs: 20,
        frameTimeoutMs: 300,
        ...(token === undefined ? {} : { token }),
      });
      cleanups.push(() => camera.stop());
      camera.start();
      await expect(camera.captureFrame()).rejects.toMatchObject({
        code: 'TIMEOUT',
        message: expect.stringContaining('401'),
      });
      expect(server.refused).toBeGreaterThan(0);
      expect(server.connections).toBe(0);
      expect(server.authorizations[0]).toBe(token === undefined ? undefined : `Bearer ${token}`);
    }
  });
});

describe('PhysicalHAL#captureFrame', () => {
  it('sends connection.cameraToken to the camera', async () => {
    const server = await cameraServer({ token: 'hal-cam-token' });
    const robot = new MockRobot({ timeScale: 20, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-cam-token',
        connection: { type: 'wifi', cameraUrl: server.url, cameraToken: 'hal-cam-token' },
      },
      { transport: robot.transport(), timeScale: 20 },
    );
    try {
      await hal.initialize();
      await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
      const timer = setInterval(() => server.send(9), 20);
      try {
        expect(decodeDataUrl(await hal.vision.captureFrame())).toEqual(jpeg(9));
      } finally {
        clearInterval(timer);
      }
      expect(server.refused).toBe(0);
    } finally {
      await hal.cleanup();
      await server.close();
    }
  });

  it('refuses a camera token with characters a URL or header cannot carry', () => {
    expect(
      () =>
        new PhysicalHAL(
          {
            mode: 'physical',
            deviceId: 'cube-cam-bad',
            connection: { type: 'wifi', cameraUrl: 'http://127.0.0.1:9', cameraToken: 'a b\r\n' },
          },
          { transport: new MockRobot().transport() },
        ),
    ).toThrow(/cameraToken/);
  });

  it('returns the camera frame when a camera URL is configured, and offers the camera capability', async () => {
    const server = await cameraServer();
    const robot = new MockRobot({ timeScale: 20, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-cam',
        connection: { type: 'wifi', cameraUrl: server.url },
      },
      { transport: robot.transport(), timeScale: 20 },
    );
    try {
      await hal.initialize();
      expect(hal.getDeviceInfo().capabilities).toContain('vision.camera:v1.0');
      await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
      const timer = setInterval(() => server.send(7), 20);
      try {
        expect(decodeDataUrl(await hal.vision.captureFrame())).toEqual(jpeg(7));
      } finally {
        clearInterval(timer);
      }
    } finally {
      await hal.cleanup();
      await server.close();
    }
  });

  it('rejects with NOT_READY after cleanup() and leaves no stream, request or timer running', async () => {
    const server = await cameraServer();
    const timers = () => process.getActiveResourcesInfo().filter((r) => r === 'Timeout').length;
    const timersBefore = timers();
    const robot = new MockRobot({ timeScale: 20, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-cam',
        connection: { type: 'wifi', cameraUrl: server.url },
      },
      { transport: robot.transport(), timeScale: 20 },
    );
    try {
      await hal.initialize();
      await expect.poll(() => server.connections, { timeout: 5000 }).toBe(1);
      await hal.cleanup();
      await expect.poll(() => server.open, { timeout: 5000 }).toBe(0);
      await expect(hal.vision.captureFrame()).rejects.toMatchObject({ code: 'NOT_READY' });
      await new Promise((resolve) => setTimeout(resolve, 100));
      expect(server.connections).toBe(1);
      expect(server.open).toBe(0);
      expect(timers()).toBeLessThanOrEqual(timersBefore);
    } finally {
      await hal.cleanup();
      await server.close();
    }
  });

  it('rejects with NOT_IMPLEMENTED when no camera is configured', async () => {
    const hal = new PhysicalHAL(
      { mode: 'physical', deviceId: 'cube-nocam' },
      { transport: new MockRobot().transport() },
    );
    await expect(hal.vision.captureFrame()).rejects.toMatchObject({ code: 'NOT_READY' });
    await hal.initialize();
    try {
      await expect(hal.vision.captureFrame()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
    } finally {
      await hal.cleanup();
    }
  });
});
