// The device manager's physical route, for real: two emulated robots (the firmware core run as
// cube-emulator), one reached over UDP and one over its pseudo-terminal, registered from config
// beside a simulated robot. All three are driven in synchronized mode and read for telemetry;
// then the UDP robot is killed (a power cut): it goes offline, its calls fail at once with
// NOT_CONNECTED and details { device, offline: true }, and the fleet e-stop still latches the
// other two, the serial robot on the firmware itself.
import { deviceFactories } from '@hal/cli';
import { DeviceManager } from '@hal/fleet/node';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';

afterAll(stopAllEmulators);

describe('physical devices in a managed fleet', () => {
  it('are driven with a simulated one, and one that dies goes offline while the e-stop latches the rest', async () => {
    const overUdp = await startEmulator({ pty: false, deviceId: 'cube-udp' });
    const overSerial = await startEmulator({ deviceId: 'cube-serial' });
    const manager = new DeviceManager(
      {
        mode: 'synchronized',
        telemetryRateHz: 4,
        offlineAfterMs: 1500,
        devices: [
          { type: 'simulated', id: 'sim', clock: 'fast' },
          {
            type: 'physical',
            id: 'cube-udp',
            connection: { type: 'wifi', host: '127.0.0.1', udpPort: overUdp.udpPort },
          },
          {
            type: 'physical',
            id: 'cube-serial',
            connection: { type: 'serial', port: overSerial.pty },
          },
        ],
      },
      // the builders the hal command gives it: SimulationHAL and PhysicalHAL
      { devices: deviceFactories() },
    );
    const offline: string[] = [];
    manager.on('offline', (e) => offline.push(e.device));
    try {
      const health = await manager.start();
      expect(health.map((h) => [h.device, h.type, h.online])).toEqual([
        ['sim', 'simulated', true],
        ['cube-udp', 'physical', true],
        ['cube-serial', 'physical', true],
      ]);
      for (const h of health) {
        expect(h.telemetry?.emergencyStopped).toBe(false);
        expect(Number.isFinite(h.telemetry?.pose.x)).toBe(true);
      }

      const report = await manager.fleet.synchronized(
        { kind: 'moveForward', distanceCm: 1 },
        { timeoutMs: 30_000 },
      );
      expect(report.failed).toEqual([]);
      expect(report.succeeded).toEqual(['sim', 'cube-udp', 'cube-serial']);
      // each robot's firmware ran the move it was sent, once
      for (const emulator of [overUdp, overSerial]) {
        expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(1);
      }
      // telemetry follows the robots: every one has moved forward from where it started
      await expect
        .poll(
          () => manager.health().map((h) => Math.hypot(h.telemetry!.pose.x, h.telemetry!.pose.y)),
          {
            timeout: 10_000,
          },
        )
        .toSatisfy((moved: number[]) => moved.every((m) => m > 0.005));

      const killedAt = Date.now();
      await overUdp.kill();
      await expect.poll(() => offline, { timeout: 20_000, interval: 100 }).toContain('cube-udp');
      expect(Date.now() - killedAt).toBeLessThan(20_000);
      expect(manager.isOnline('cube-udp')).toBe(false);
      expect(manager.health().find((h) => h.device === 'cube-udp')?.lastError).toBeDefined();

      const gone = manager.createDeviceHAL('cube-udp');
      const started = Date.now();
      expect(await gone.locomotion.moveForward(1)).toMatchObject({
        success: false,
        code: 'NOT_CONNECTED',
        details: { device: 'cube-udp', offline: true },
      });
      await expect(gone.vision.getIMU()).rejects.toMatchObject({
        code: 'NOT_CONNECTED',
        details: { device: 'cube-udp', offline: true },
      });
      expect(Date.now() - started).toBeLessThan(1000); // at once, not after a timeout

      const estop = await manager.emergencyStop('fleet stop');
      expect(estop.succeeded).toEqual(expect.arrayContaining(['sim', 'cube-serial']));
      const trip = await overSerial.waitFor(
        (e) => e.event === 'trip' && e['reason'] === 'estop_command',
        10_000,
      );
      expect(trip['estop']).toBe(true);
      for (const id of ['sim', 'cube-serial']) {
        const hal = manager.createDeviceHAL(id);
        expect(hal.safety.isEmergencyStopped()).toBe(true);
        expect(await hal.locomotion.moveForward(1)).toMatchObject({
          success: false,
          code: 'EMERGENCY_STOPPED',
        });
      }
      expect(overSerial.events.filter((e) => e.event === 'move_started')).toHaveLength(1);
    } finally {
      await manager.stop();
    }
  }, 90_000);
});
