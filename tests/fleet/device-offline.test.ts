// A device that disappears from a managed fleet on a real nats-server: its robot host is killed
// mid-run. The manager sees it offline (an event), its calls fail at once with NOT_CONNECTED and
// details { device, offline: true }, nothing hangs, and the other robots go on; when its host
// comes back, so does the device.
import { DeviceManager } from '@hal/fleet/node';
import { afterAll, describe, expect, it } from 'vitest';
import { startHostProcess, stopAllHostProcesses } from '../physical/host-process.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';

afterAll(async () => {
  await stopAllHostProcesses();
  await stopAllNatsServers();
});

describe('a managed device that disappears', () => {
  it('goes offline, fails its calls NOT_CONNECTED at once, and the others go on', async () => {
    const server = await startNatsServer();
    const stays = startHostProcess('../../fleet/processes/fleet-gateways.ts', [
      server.url,
      'a',
      '3',
      '4',
    ]);
    const goes = startHostProcess('../../fleet/processes/fleet-gateways.ts', [
      server.url,
      'b',
      '1',
      '4',
    ]);
    await stays.waitFor((e) => e.event === 'serving', 30_000);
    await goes.waitFor((e) => e.event === 'serving', 30_000);
    const manager = new DeviceManager({
      nats: { servers: server.url },
      telemetryRateHz: 4,
      offlineAfterMs: 1500,
      devices: ['a00', 'a01', 'a02', 'b00'].map((id) => ({ type: 'nats', id })),
    });
    const events: string[] = [];
    manager.on('online', (e) => events.push(`online ${e.device}`));
    manager.on('offline', (e) => events.push(`offline ${e.device}`));
    try {
      await manager.start();
      expect(manager.health().every((h) => h.online)).toBe(true);
      const offline = new Promise<number>((resolve) =>
        manager.on('offline', (e) => {
          if (e.device === 'b00') resolve(Date.now());
        }),
      );
      const killedAt = Date.now();
      await goes.kill();
      const seenAt = await offline;
      expect(seenAt - killedAt).toBeLessThan(15_000);
      expect(events).toContain('offline b00');
      expect(manager.isOnline('b00')).toBe(false);
      expect(manager.health().find((h) => h.device === 'b00')?.lastError).toBeDefined();

      const gone = manager.createDeviceHAL('b00');
      const started = Date.now();
      const moved = await gone.locomotion.moveForward(1);
      expect(moved).toMatchObject({
        success: false,
        code: 'NOT_CONNECTED',
        details: { device: 'b00', offline: true },
      });
      await expect(gone.locomotion.getPose()).rejects.toMatchObject({
        code: 'NOT_CONNECTED',
        details: { device: 'b00', offline: true },
      });
      expect(gone.isReady()).toBe(false);
      // "at once": far below any call or offline timeout
      expect(Date.now() - started).toBeLessThan(1000);

      const report = await manager.fleet.synchronized(
        { kind: 'moveForward', distanceCm: 1 },
        { timeoutMs: 20_000 },
      );
      expect(report.succeeded).toEqual(['a00', 'a01', 'a02']);
      expect(report.failed).toEqual(['b00']);
      expect(report.results[3]?.result.code).toBe('NOT_CONNECTED');
      expect(
        manager
          .health()
          .filter((h) => h.online)
          .map((h) => h.device),
      ).toEqual(['a00', 'a01', 'a02']);
    } finally {
      await manager.stop();
    }
  }, 60_000);
});
