// Faults around a device on NATS: the gateway process killed (the device disappears), and the
// NATS server restarted mid-run. Nothing hangs, failures carry a clear code, and no command is
// executed twice (executions are counted on the served HAL).
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
import { makeEnvelope } from '@hal/types';
import { connect } from '@nats-io/transport-node';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { startHostProcess, stopAllHostProcesses } from '../physical/host-process.js';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';

const cleanups: Array<() => Promise<void>> = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
});
afterAll(async () => {
  await stopAllHostProcesses();
  await stopAllNatsServers();
});

describe('a device that disappears', () => {
  it(
    'is detected offline, and its calls fail NOT_CONNECTED without hanging',
    { timeout: 40_000 },
    async () => {
      const server = await startNatsServer();
      const gateway = startHostProcess('../../nats/processes/sim-gateway.ts', [
        server.url,
        'sim-gone',
      ]);
      await gateway.waitFor((e) => e.event === 'serving', 20_000);
      const hal = new NatsHAL({ servers: server.url, deviceId: 'sim-gone', offlineAfterMs: 1500 });
      cleanups.push(() => hal.cleanup());
      await hal.initialize();
      expect(hal.isReady()).toBe(true);

      // A 5 cm move takes about a second in real time; the device dies in the middle of it.
      const moving = hal.locomotion.moveForward(5);
      await new Promise((resolve) => setTimeout(resolve, 300));
      await gateway.kill();

      const started = Date.now();
      const inFlight = await moving;
      expect(inFlight.success).toBe(false);
      expect(inFlight.code).toBe('NOT_CONNECTED');
      // The same code and details the device manager's offline guard gives.
      expect(inFlight.details).toMatchObject({ device: 'sim-gone', offline: true });
      const next = await hal.locomotion.moveForward(1);
      expect(next.code).toBe('NOT_CONNECTED');
      expect(next.details).toMatchObject({ device: 'sim-gone', offline: true });
      await expect(hal.locomotion.getPose()).rejects.toMatchObject({
        code: 'NOT_CONNECTED',
        details: { device: 'sim-gone', offline: true },
      });
      expect(hal.isReady()).toBe(false);
      // Bounded by the offline window plus slack, far below the 120 s call timeout.
      expect(Date.now() - started).toBeLessThan(10_000);
    },
  );
});

describe('a device that is not there', () => {
  it(
    'fails initialize() with NOT_CONNECTED at once rather than waiting out the call timeout',
    { timeout: 20_000 },
    async () => {
      const server = await startNatsServer();
      const hal = new NatsHAL({ servers: server.url, deviceId: 'nobody-home' });
      cleanups.push(() => hal.cleanup());
      const started = Date.now();
      await expect(hal.initialize()).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
      expect(Date.now() - started).toBeLessThan(5000);
      expect(hal.isReady()).toBe(false);
      expect((await hal.locomotion.moveForward(1)).code).toBe('NOT_READY');
    },
  );
});

describe('the NATS server restarted mid-run', () => {
  it(
    'reconnects the gateway and the client, and runs no command twice',
    { timeout: 60_000 },
    async () => {
      const server = await startNatsServer();
      const device = new SimulationHAL({ clock: 'realtime' });
      await device.initialize();
      cleanups.push(() => device.cleanup());
      const executions: string[] = [];
      const forward = device.locomotion.moveForward.bind(device.locomotion);
      device.locomotion.moveForward = (cm: number) => {
        executions.push(`forward ${cm}`);
        return forward(cm);
      };
      const gateway = await serveHalOnNats(device, {
        servers: server.url,
        deviceId: 'sim-restart',
      });
      cleanups.push(() => gateway.close());
      const hal = new NatsHAL({
        servers: server.url,
        deviceId: 'sim-restart',
        attemptTimeoutMs: 500,
        offlineAfterMs: 5000,
      });
      cleanups.push(() => hal.cleanup());
      await hal.initialize();

      const moving = hal.locomotion.moveForward(5);
      await new Promise((resolve) => setTimeout(resolve, 300));
      await server.restart();
      const result = await moving;
      expect(result.success, JSON.stringify(result)).toBe(true);

      for (const cm of [1, 2]) expect((await hal.locomotion.moveForward(cm)).success).toBe(true);
      expect(executions).toEqual(['forward 5', 'forward 1', 'forward 2']);
      const pose = await hal.locomotion.getPose();
      expect(pose.position.x).toBeCloseTo(0.08, 2);
    },
  );
});

describe('a controller that vanishes during an open-ended drive', () => {
  it(
    'has its drive stopped by the gateway, while a NatsHAL that keeps its heartbeat keeps driving',
    { timeout: 40_000 },
    async () => {
      const server = await startNatsServer();
      const device = new SimulationHAL({ clock: 'realtime' });
      await device.initialize();
      cleanups.push(() => device.cleanup());
      const gateway = await serveHalOnNats(device, {
        servers: server.url,
        deviceId: 'sim-watch',
        controllerTimeoutMs: 800,
      });
      cleanups.push(() => gateway.close());

      // A client that starts a drive with no end and then says nothing more (as if it crashed).
      const nc = await connect({ servers: server.url });
      const call = makeEnvelope(
        { schema: 'call', device_id: 'vanishing-agent' },
        { request_id: 'open-drive', call: 'locomotion.drive', args: [100, 100] },
      );
      await nc.request(
        'hal.v1.dev.sim-watch.hal.call.req',
        new TextEncoder().encode(JSON.stringify(call)),
        {
          timeout: 5000,
        },
      );
      await nc.close();
      const started = Date.now();
      await new Promise((resolve) => setTimeout(resolve, 300));
      expect((await device.locomotion.getPose()).velocity.linear).toBeGreaterThan(0);
      while (
        (await device.locomotion.getPose()).velocity.linear > 0 &&
        Date.now() - started < 10_000
      ) {
        await new Promise((resolve) => setTimeout(resolve, 50));
      }
      expect((await device.locomotion.getPose()).velocity.linear).toBe(0);
      expect(Date.now() - started).toBeLessThan(10_000);

      // NatsHAL heartbeats: its open-ended drive outlives the controller timeout.
      const hal = new NatsHAL({ servers: server.url, deviceId: 'sim-watch', heartbeatMs: 200 });
      cleanups.push(() => hal.cleanup());
      await hal.initialize();
      expect((await hal.locomotion.drive(100, 100)).success).toBe(true);
      await new Promise((resolve) => setTimeout(resolve, 1600));
      expect((await device.locomotion.getPose()).velocity.linear).toBeGreaterThan(0);
      expect((await hal.locomotion.stop()).success).toBe(true);
    },
  );
});

describe('a device no one serves', () => {
  it('fails NOT_CONNECTED at once, saying no one serves it and claiming no time it did not wait', async () => {
    const server = await startNatsServer();
    const hal = new NatsHAL({ servers: server.url, deviceId: 'nobody', offlineAfterMs: 60_000 });
    cleanups.push(() => hal.cleanup());
    await expect(hal.initialize()).rejects.toMatchObject({
      code: 'NOT_CONNECTED',
      message:
        'device "nobody" is offline: it has not answered on "hal.v1.dev.nobody.system.capability.req": no one serves it',
      details: { device: 'nobody', offline: true },
    });
    expect(hal.isReady()).toBe(false);
  });
});
