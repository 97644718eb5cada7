import { SimulationHAL } from '@hal/simulation';
import { isHalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { WebSocketServer } from 'ws';
import { serveHal } from '../server/index.js';
import type { HalServer, ServeHalOptions } from '../server/index.js';
import { RemoteHAL } from './remote-hal.js';
import type { RemoteHALOptions } from './options.js';

const cleanups: Array<() => Promise<unknown>> = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
});

async function served(
  options: ServeHalOptions = {},
): Promise<{ sim: SimulationHAL; server: HalServer }> {
  const sim = new SimulationHAL();
  await sim.initialize();
  const server = await serveHal(sim, { port: 0, ...options });
  cleanups.push(
    () => sim.cleanup(),
    () => server.close(),
  );
  return { sim, server };
}
function remote(options: RemoteHALOptions): RemoteHAL {
  const hal = new RemoteHAL(options);
  cleanups.push(() => hal.cleanup());
  return hal;
}

describe('RemoteHAL', () => {
  it("passes on a served HAL's mark that its pose is predicted, not confirmed", async () => {
    const sim = new SimulationHAL();
    await sim.initialize();
    // a physical robot's HAL marks the pose it predicts after a lost link
    const getPose = async () => ({ ...(await sim.locomotion.getPose()), confirmed: false });
    const predicting: HardwareAbstractionLayer = {
      mode: sim.mode,
      locomotion: { ...sim.locomotion, getPose },
      vision: sim.vision,
      communication: sim.communication,
      safety: sim.safety,
      initialize: () => sim.initialize(),
      cleanup: () => sim.cleanup(),
      isReady: () => sim.isReady(),
      getDeviceInfo: () => sim.getDeviceInfo(),
    };
    const server = await serveHal(predicting, { port: 0 });
    cleanups.push(
      () => sim.cleanup(),
      () => server.close(),
    );
    const hal = remote({ url: server.url });
    await hal.initialize();
    expect((await hal.locomotion.getPose()).confirmed).toBe(false);
  });

  it('answers isEmergencyStopped() synchronously from the streamed state when another client stops the robot', async () => {
    const { server } = await served({ stateRateHz: 50 });
    const driver = remote({ url: server.url });
    const watcher = remote({ url: server.url });
    await driver.initialize();
    await watcher.initialize();
    expect(driver.role).toBe('controller');
    expect(watcher.role).toBe('watcher');
    expect((await watcher.safety.emergencyStop('seen from the side')).success).toBe(true);
    await vi.waitFor(() => expect(driver.safety.isEmergencyStopped()).toBe(true), {
      timeout: 2000,
    });
    expect(driver.safety.getSafetyStatus().emergencyStopReason).toContain('seen from the side');
    expect((await watcher.safety.resetEmergencyStop()).code).toBe('NOT_CONTROLLER');
    expect((await driver.safety.resetEmergencyStop()).success).toBe(true);
    expect(driver.safety.isEmergencyStopped()).toBe(false);
  });

  it('latches an e-stop before initialize() on the host, and sends it to the server before reporting ready', async () => {
    const { server, sim } = await served();
    const hal = remote({ url: server.url });
    const stop = await hal.safety.emergencyStop('cliff\u0007ahead  ');
    expect(stop).toMatchObject({
      success: true,
      data: { estop: true, reason: 'cliff ahead', delivered: false },
    });
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('cliff ahead');
    expect(sim.safety.isEmergencyStopped()).toBe(false);
    await hal.initialize();
    expect(sim.safety.isEmergencyStopped()).toBe(true);
    expect(sim.safety.getSafetyStatus().emergencyStopReason).toBe('cliff ahead');
    expect(hal.safety.getSafetyStatus()).toMatchObject({
      emergencyStopped: true,
      emergencyStopReason: 'cliff ahead',
    });
    expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
    expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
    expect(hal.safety.isEmergencyStopped()).toBe(false);
    expect(sim.safety.isEmergencyStopped()).toBe(false);
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
  });

  it('latches an e-stop after cleanup() with its reason sanitized, and reports the sanitized reason with a link', async () => {
    const { server } = await served();
    const hal = remote({ url: server.url });
    await hal.initialize();
    const live = await hal.safety.emergencyStop(' too\r\nclose ');
    expect(live).toMatchObject({ success: true, data: { reason: 'too close', delivered: true } });
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('too close');
    expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
    await hal.cleanup();
    const stop = await hal.safety.emergencyStop(7 as unknown as string);
    expect(stop).toMatchObject({ success: true, data: { reason: '7', delivered: false } });
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect(hal.safety.getSafetyStatus().emergencyStopReason).toBe('7');
  });

  it('keeps an e-stop made while the server is away latched here, and sends it on reconnection', async () => {
    const sim = new SimulationHAL();
    await sim.initialize();
    cleanups.push(() => sim.cleanup());
    let server = await serveHal(sim, { port: 0 });
    const port = server.address.port;
    const hal = remote({ url: server.url, reconnectDelayMs: 50 });
    await hal.initialize();
    await server.close();
    await vi.waitFor(() => expect(hal.isReady()).toBe(false), { timeout: 2000 });
    expect(await hal.safety.emergencyStop('link down')).toMatchObject({
      success: true,
      data: { reason: 'link down', delivered: false },
    });
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    server = await serveHal(sim, { port });
    cleanups.push(() => server.close());
    await vi.waitFor(() => expect(sim.safety.isEmergencyStopped()).toBe(true), { timeout: 5000 });
    expect(sim.safety.getSafetyStatus().emergencyStopReason).toBe('link down');
    expect(hal.safety.isEmergencyStopped()).toBe(true);
    expect((await hal.locomotion.moveForward(1)).code).toBe('EMERGENCY_STOPPED');
    expect((await hal.safety.resetEmergencyStop()).success).toBe(true);
    expect(hal.safety.isEmergencyStopped()).toBe(false);
  });

  it('refuses motion from a watcher with NOT_CONTROLLER until it takes control, and tells the old controller', async () => {
    const { server } = await served();
    const first = remote({ url: server.url });
    const second = remote({ url: server.url });
    await first.initialize();
    await second.initialize();
    const result = await second.locomotion.moveForward(1);
    expect(result).toMatchObject({ success: false, code: 'NOT_CONTROLLER' });
    const told = new Promise<string>((resolve) => first.onRoleChange((role) => resolve(role)));
    await second.takeControl();
    expect(await told).toBe('watcher');
    expect(second.role).toBe('controller');
    expect((await second.locomotion.moveForward(1)).success).toBe(true);
    expect((await first.locomotion.moveForward(1)).code).toBe('NOT_CONTROLLER');
  });

  it("names the device by the server's deviceId, else by the served HAL's own id", async () => {
    const named = await served({ deviceId: 'cube-emulator' });
    const hal = remote({ url: named.server.url });
    await hal.initialize();
    expect(hal.getDeviceInfo()).toMatchObject({
      id: 'cube-emulator',
      type: named.sim.getDeviceInfo().type,
      capabilities: named.sim.getDeviceInfo().capabilities,
    });
    const plain = await served();
    const other = remote({ url: plain.server.url });
    await other.initialize();
    expect(other.getDeviceInfo().id).toBe(plain.sim.getDeviceInfo().id);
  });

  it("with control: 'take', takes control on connecting", async () => {
    const { server } = await served();
    const first = remote({ url: server.url });
    await first.initialize();
    const second = remote({ url: server.url, control: 'take' });
    await second.initialize();
    expect(second.role).toBe('controller');
    await vi.waitFor(() => expect(first.role).toBe('watcher'));
  });

  it("with control: 'watch', never controls, even when it arrives first", async () => {
    const { server } = await served();
    const watcher = remote({ url: server.url, control: 'watch' });
    await watcher.initialize();
    expect(watcher.role).toBe('watcher');
    expect((await watcher.locomotion.moveForward(1)).code).toBe('NOT_CONTROLLER');
    const driver = remote({ url: server.url });
    await driver.initialize();
    expect(driver.role).toBe('controller');
  });

  it('keeps control past the heartbeat timeout while idle, because it sends heartbeats', async () => {
    const { server } = await served({ heartbeatTimeoutMs: 300 });
    const hal = remote({ url: server.url });
    await hal.initialize();
    await new Promise((r) => setTimeout(r, 1000));
    expect(hal.isReady()).toBe(true);
    expect(hal.role).toBe('controller');
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
  });

  it('fails calls with NOT_CONNECTED when the server goes away, and reconnects when it is back', async () => {
    const sim = new SimulationHAL();
    await sim.initialize();
    cleanups.push(() => sim.cleanup());
    let server = await serveHal(sim, { port: 0 });
    const port = server.address.port;
    const hal = remote({ url: server.url, reconnectDelayMs: 50 });
    await hal.initialize();
    await server.close();
    await vi.waitFor(() => expect(hal.isReady()).toBe(false), { timeout: 2000 });
    expect(await hal.locomotion.moveForward(1)).toMatchObject({
      success: false,
      code: 'NOT_CONNECTED',
    });
    const rejected: unknown = await hal.locomotion.getPose().catch((e: unknown) => e);
    expect(isHalError(rejected) && rejected.code).toBe('NOT_CONNECTED');
    server = await serveHal(sim, { port });
    cleanups.push(() => server.close());
    await vi.waitFor(() => expect(hal.isReady()).toBe(true), { timeout: 5000 });
    expect((await hal.locomotion.moveForward(1)).success).toBe(true);
  });

  it('rejects initialize() with NOT_CONNECTED when nothing listens, within the connect timeout', async () => {
    const hal = remote({ url: 'ws://127.0.0.1:1', connectTimeoutMs: 2000 });
    const error: unknown = await hal.initialize().catch((e: unknown) => e);
    expect(isHalError(error) && error.code).toBe('NOT_CONNECTED');
    expect(hal.isReady()).toBe(false);
  });

  it('bounds every wait: a server that never replies makes a call fail with TIMEOUT', async () => {
    // A server that says hello, then ignores everything.
    const mute = new WebSocketServer({ host: '127.0.0.1', port: 0 });
    cleanups.push(() => new Promise((resolve) => mute.close(resolve)));
    mute.on('connection', (socket) => {
      socket.send(
        JSON.stringify({
          hal_major: 1,
          hal_minor: 0,
          schema: 'hal.remote.hello',
          device_id: 'mute',
          caps: [],
          ts: Date.now(),
          payload: {
            session_id: 's',
            role: 'controller',
            mode: 'simulation',
            device: { id: 'mute', type: 'test', mode: 'simulation', capabilities: [] },
            heartbeat_timeout_ms: 2000,
            state_rate_hz: 10,
            max_message_bytes: 65536,
          },
        }),
      );
    });
    await new Promise((resolve) => mute.once('listening', resolve));
    const { port } = mute.address() as { port: number };
    const hal = remote({
      url: `ws://127.0.0.1:${port}`,
      requestTimeoutMs: 300,
      motionTimeoutMs: 300,
    });
    await hal.initialize();
    const started = Date.now();
    expect(await hal.locomotion.moveForward(1)).toMatchObject({ success: false, code: 'TIMEOUT' });
    const error: unknown = await hal.vision.getIMU().catch((e: unknown) => e);
    expect(isHalError(error) && error.code).toBe('TIMEOUT');
    expect(Date.now() - started).toBeLessThan(3000);
  });

  it('presents the token, and is refused without it or with a wrong one as AUTH_FAILED (HTTP 401)', async () => {
    const token = 'a-long-enough-secret-token';
    const { server } = await served({ token });
    const without = remote({ url: server.url, reconnect: false });
    const error: unknown = await without.initialize().catch((e: unknown) => e);
    expect(isHalError(error) && error.code).toBe('AUTH_FAILED');
    expect(String(error)).toMatch(/refused the connection \(HTTP 401\): no token was given/);
    const wrong = remote({ url: server.url, token: 'not-the-right-token', reconnect: false });
    const wrongError: unknown = await wrong.initialize().catch((e: unknown) => e);
    expect(isHalError(wrongError) && wrongError.code).toBe('AUTH_FAILED');
    expect(String(wrongError)).toMatch(/\(HTTP 401\): the token is wrong/);
    const withToken = remote({ url: server.url, token });
    await withToken.initialize();
    expect(withToken.isReady()).toBe(true);
  });
});
