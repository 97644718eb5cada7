// serveHal's WebSocket door against web pages: without a token it lets in programs (no Origin)
// and pages served from this machine, and refuses, before any hello, a page from another site
// and a DNS-rebound Host; `allowedOrigins` and the token let a page in. Real `ws` clients, a
// server on a free port.
import { RemoteHAL } from '@hal/remote';
import type { WebSocketConstructor } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import type { HalServer, ServeHalOptions } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import { WebSocket } from 'ws';
import { afterEach, describe, expect, it } from 'vitest';
import { knock } from './knock.js';

let server: HalServer | undefined;
let sim: SimulationHAL | undefined;
const remotes: RemoteHAL[] = [];

async function serve(options: ServeHalOptions = {}): Promise<HalServer> {
  sim = new SimulationHAL();
  await sim.initialize();
  server = await serveHal(sim, { port: 0, ...options });
  return server;
}

afterEach(async () => {
  await Promise.all(remotes.splice(0).map((hal) => hal.cleanup()));
  await server?.close();
  await sim?.cleanup();
  server = undefined;
  sim = undefined;
});

const FOREIGN = 'http://evil.example';

describe('the WebSocket door without a token', () => {
  it('refuses a page from another site with 403 before the hello, so it never controls the robot', async () => {
    const { url } = await serve();
    const refused = await knock(url, { origin: FOREIGN });
    expect(refused).toMatchObject({ opened: false, status: 403 });
    expect(refused.opened === false && refused.body).toMatch(
      /Origin "http:\/\/evil\.example" .*not trusted.*--allow-origin http:\/\/evil\.example/,
    );
    expect(server!.clientCount()).toBe(0);
    // nobody took control: the next client (a program) is the controller
    expect(await knock(url)).toEqual({ opened: true, role: 'controller' });
  });

  it('lets in a program that sends no Origin, and pages served from this machine', async () => {
    const { url } = await serve({ host: '127.0.0.1' });
    expect(await knock(url)).toMatchObject({ opened: true });
    for (const origin of [
      'http://localhost:5173',
      'http://127.0.0.1:4173',
      'https://localhost',
      'http://[::1]:8080',
    ]) {
      expect(await knock(url, { origin }), origin).toMatchObject({ opened: true });
    }
  });

  it('refuses an opaque origin ("null": a sandboxed frame or a file) and an unreadable one', async () => {
    const { url } = await serve();
    for (const origin of ['null', 'not an origin']) {
      expect(await knock(url, { origin }), origin).toMatchObject({ opened: false, status: 403 });
    }
  });

  it('refuses a Host that is not a loopback name (DNS rebinding), whatever the Origin', async () => {
    const { url, address } = await serve();
    const host = `rebound.evil.example:${address.port}`;
    for (const headers of [{ host }, { host, origin: `http://${host}` }]) {
      const refused = await knock(url, headers);
      expect(refused).toMatchObject({ opened: false, status: 403 });
      expect(refused.opened === false && refused.body).toMatch(
        /Host "rebound\.evil\.example:\d+" is not a loopback name/,
      );
    }
    expect(await knock(url, { host: `localhost:${address.port}` })).toMatchObject({
      opened: true,
    });
  });

  it('lets in the origins it was told to trust, and only those', async () => {
    const { url } = await serve({
      allowedOrigins: ['https://App.Example/', 'http://10.0.0.5:5173'],
    });
    expect(await knock(url, { origin: 'https://app.example' })).toMatchObject({ opened: true });
    expect(await knock(url, { origin: 'http://10.0.0.5:5173' })).toMatchObject({ opened: true });
    for (const origin of ['http://app.example', 'https://app.example:8443', FOREIGN]) {
      expect(await knock(url, { origin }), origin).toMatchObject({ opened: false, status: 403 });
    }
  });

  it('refuses to start with an origin that is not one (INVALID_PARAMETER), before listening', async () => {
    for (const origin of ['app.example', 'https://app.example/page', '*', 'null']) {
      const s = new SimulationHAL();
      await expect(
        serveHal(s, { port: 0, allowedOrigins: [origin] }),
        origin,
      ).rejects.toMatchObject({
        code: 'INVALID_PARAMETER',
        details: { parameter: 'allowedOrigins', received: origin },
      });
    }
  });

  it('names the refusal to a RemoteHAL: AUTH_FAILED, HTTP 403, and what would let it in', async () => {
    const { url } = await serve();
    // a WebSocket that sends a foreign Origin, as a page on another site does
    class FromForeignPage extends WebSocket {
      constructor(address: string) {
        super(address, { headers: { origin: FOREIGN } });
      }
    }
    const hal = new RemoteHAL({
      url,
      reconnect: false,
      // ws types its handlers' events more narrowly than the client's WebSocketLike reads them
      WebSocket: FromForeignPage as unknown as WebSocketConstructor,
    });
    remotes.push(hal);
    await expect(hal.initialize()).rejects.toMatchObject({
      code: 'AUTH_FAILED',
      message: expect.stringMatching(/\(HTTP 403\): .*Origin or Host.*--allow-origin/),
    });
  });
});

describe('the WebSocket door with a token', () => {
  const token = 'door-token-0123456789';

  it('lets in any page that presents the token, and refuses one without it (401)', async () => {
    const { url } = await serve({ token });
    expect(await knock(url, { origin: FOREIGN, authorization: `Bearer ${token}` })).toMatchObject({
      opened: true,
    });
    expect(await knock(`${url}/?token=${token}`, { origin: FOREIGN })).toMatchObject({
      opened: true,
    });
    const refused = await knock(url, { origin: 'http://localhost:5173' });
    expect(refused).toMatchObject({ opened: false, status: 401 });
    expect(refused.opened === false && refused.body).toMatch(/a token is required/);
  });
});
