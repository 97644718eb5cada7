// Faults around a device on NATS: the gateway process killed (the device disappears), and the
// NATS server restarted mid-run. Nothing hangs, failures carry a clear code, and no command is
// executed twice (executions are counted on the served HAL).
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';
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
      const next = await hal.locomotion.moveForward(1);
      expect(next.code).toBe('NOT_CONNECTED');
      await expect(hal.locomotion.getPose()).rejects.toMatchObject({ code: 'NOT_CONNECTED' });
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
