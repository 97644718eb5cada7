// The emulated ESP32-CAM's HTTP interface on a real socket, against what the sketch answers.
import { connect } from 'node:net';
import { afterEach, describe, expect, it } from 'vitest';
import { startCameraServer } from './camera-server.js';
import type { CameraServer, CameraServerOptions } from './camera-server.js';

/** A stand-in JPEG: SOI, a byte that counts the frames, EOI. */
let made = 0;
const frame = () => Promise.resolve(Uint8Array.of(0xff, 0xd8, made++ & 0xff, 0xff, 0xd9));

const servers: CameraServer[] = [];
afterEach(async () => {
  for (const s of servers.splice(0)) await s.close();
});

async function start(options: Partial<CameraServerOptions> = {}) {
  const server = await startCameraServer({ host: '127.0.0.1', port: 0, frame, ...options });
  servers.push(server);
  return { server, base: `http://127.0.0.1:${server.port}` };
}

/** Sends `request` as raw bytes and reads what comes back until `enough` or the socket ends. */
function raw(port: number, request: string, enough = (_: string) => false): Promise<string> {
  return new Promise((resolve, reject) => {
    const socket = connect(port, '127.0.0.1');
    let text = '';
    const timer = setTimeout(() => {
      socket.destroy();
      reject(new Error(`no end within 5 s; got ${JSON.stringify(text.slice(0, 300))}`));
    }, 5000);
    const done = () => {
      clearTimeout(timer);
      socket.destroy();
      resolve(text);
    };
    socket.on('data', (chunk) => {
      text += chunk.toString('latin1');
      if (enough(text)) done();
    });
    socket.on('end', done);
    socket.on('error', reject);
    socket.write(request);
  });
}

describe('the emulated camera server', () => {
  it('streams JPEG parts at the sketch boundary, unchunked, and counts them in /status', async () => {
    const { server } = await start();
    const text = await raw(
      server.port,
      'GET /stream HTTP/1.1\r\nHost: x\r\n\r\n',
      (t) => t.split('--cubeframe\r\n').length > 3,
    );
    const [head, ...parts] = text.split('--cubeframe\r\n');
    expect(head).toMatch(/^HTTP\/1\.1 200 OK\r\n/);
    expect(head).toContain('Content-Type: multipart/x-mixed-replace; boundary=cubeframe\r\n');
    expect(head).toContain('Cache-Control: no-cache\r\n');
    expect(head).toContain('Connection: close\r\n');
    expect(head).not.toMatch(/Transfer-Encoding|Content-Length|^Date:/im);
    expect(parts[0]).toMatch(
      /^Content-Type: image\/jpeg\r\nContent-Length: 5\r\n\r\n\xff\xd8.\xff\xd9\r\n$/s,
    );
    const status = (await (await fetch(`http://127.0.0.1:${server.port}/status`)).json()) as Record<
      string,
      unknown
    >;
    expect(status).toMatchObject({ rssi_dbm: 0, width: 320, height: 240 });
    expect(status['frames_served']).toBeGreaterThanOrEqual(3);
    expect(Object.keys(status).sort()).toEqual(
      ['fps', 'frames_served', 'height', 'rssi_dbm', 'stream_clients', 'uptime_ms', 'width'].sort(),
    );
  });

  it('asks for the token on /stream and /status, by header or query, and not on the page', async () => {
    const { base } = await start({ token: 'cam-token_1' });
    for (const path of ['/stream', '/status']) {
      const bare = await fetch(`${base}${path}`);
      expect(bare.status).toBe(401);
      expect(bare.headers.get('www-authenticate')).toBe('Bearer realm="cube-camera"');
      expect(await bare.text()).toBe('a token is required: ?token= or Authorization: Bearer\n');
      const wrong = await fetch(`${base}${path}`, {
        headers: { Authorization: 'Bearer cam-token_2' },
      });
      expect(wrong.status).toBe(401);
      await wrong.body?.cancel();
    }
    const status = await fetch(`${base}/status`, {
      headers: { Authorization: 'Bearer cam-token_1' },
    });
    expect(status.status).toBe(200);
    expect(status.headers.get('content-type')).toBe('application/json');
    await status.body?.cancel();
    const byQuery = await fetch(`${base}/status?token=cam-token_1`);
    expect(byQuery.status).toBe(200);
    await byQuery.body?.cancel();
    const page = await fetch(`${base}/`);
    expect(page.status).toBe(200);
    expect(await page.text()).toContain("'/stream'+location.search");
  });

  it('answers 404, 405 (OPTIONS too: no origin is configured) and 431 as the sketch does', async () => {
    const { server, base } = await start();
    const missing = await fetch(`${base}/nothing`);
    expect([missing.status, await missing.text()]).toEqual([404, 'not found\n']);
    for (const method of ['POST', 'OPTIONS']) {
      const refused = await fetch(`${base}/stream`, { method });
      expect([refused.status, await refused.text()]).toEqual([405, 'only GET\n']);
    }
    const huge = await raw(
      server.port,
      `GET /status HTTP/1.1\r\nX-Pad: ${'a'.repeat(2000)}\r\n\r\n`,
    );
    expect(huge).toMatch(/^HTTP\/1\.1 431 /);
  });

  it('serves two streams at once and answers a third with 503', async () => {
    const { server, base } = await start();
    const controller = new AbortController();
    const first = await fetch(`${base}/stream`, { signal: controller.signal });
    const second = await fetch(`${base}/stream`, { signal: controller.signal });
    expect([first.status, second.status]).toEqual([200, 200]);
    expect(server.status().stream_clients).toBe(2);
    const third = await fetch(`${base}/stream`);
    expect([third.status, await third.text()]).toEqual([503, 'busy, try again\n']);
    controller.abort();
    const deadline = Date.now() + 5000;
    while (server.status().stream_clients > 0 && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 20));
    }
    expect(server.status().stream_clients).toBe(0);
  });
});
