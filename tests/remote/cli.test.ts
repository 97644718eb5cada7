// `hal serve --ws-port`, run as a user runs it, serving PhysicalHAL to the emulated robot and
// the embedded simulator; RemoteHAL drives each over a real WebSocket.
import { RemoteHAL } from '@hal/remote';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startServe as serve, stopAllServes } from './serve-command.js';

const hals: RemoteHAL[] = [];

afterEach(async () => {
  await Promise.all(hals.splice(0).map((hal) => hal.cleanup()));
  stopAllServes();
});
afterAll(stopAllEmulators);

describe('hal serve on WebSocket', () => {
  it('serves PhysicalHAL to the emulated robot with one command', async () => {
    const emulator = await startEmulator({ timeScale: 20, hostTimeoutMs: 10_000, pty: false });
    const url = await serve([
      '--udp',
      `127.0.0.1:${emulator.udpPort}`,
      '--time-scale',
      '20',
      '--device',
      'cube-served',
    ]);
    const hal = new RemoteHAL({ url });
    hals.push(hal);
    await hal.initialize();
    expect(hal.mode).toBe('physical');
    expect(hal.getDeviceInfo().id).toBe('cube-served');
    expect((await hal.locomotion.moveForward(5)).success).toBe(true);
    expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.05, 2);
  });

  it('serves the simulator, with a token taken from the environment', async () => {
    const token = 'token-from-the-environment';
    const url = await serve(['--sim'], { HAL_SERVE_TOKEN: token });
    const refused = new RemoteHAL({ url, reconnect: false });
    hals.push(refused);
    // the server answered 401: a refused token, not a server that is not there
    await expect(refused.initialize()).rejects.toMatchObject({
      code: 'AUTH_FAILED',
      message: expect.stringMatching(/refused the connection \(HTTP 401\): no token was given/),
    });
    const hal = new RemoteHAL({ url, token });
    hals.push(hal);
    await hal.initialize();
    expect(hal.mode).toBe('simulation');
    expect((await hal.locomotion.rotate('left', 10)).success).toBe(true);
  });

  it('refuses to listen beyond loopback without a token, and says why', async () => {
    const error = await serve(['--sim', '--host', '0.0.0.0']).catch((e: unknown) => e);
    expect(error).toMatchObject({ exitCode: 1 });
    expect(String(error)).toMatch(/needs a token/);
  });

  it('refuses a malformed robot address with a usage error', async () => {
    const error = await serve(['--udp', 'robot:0']).catch((e: unknown) => e);
    expect(error).toMatchObject({ exitCode: 2 });
    expect(String(error)).toMatch(/"--udp" must be HOST(,| or) HOST:PORT/);
  });
});
