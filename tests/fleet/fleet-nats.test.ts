// A fleet on a real nats-server: 50 simulated robots in one world, served by one robot-host
// process (one gateway per robot), managed by a DeviceManager that drives each through a NatsHAL.
// Synchronized mode reports every robot's own result (a robot that is not there fails alone),
// leader-follower keeps the grid's shape while the leader moves, and the fleet e-stop latches
// every robot on the device itself.
import { DeviceManager } from '@hal/fleet/node';
import type { FleetReport } from '@hal/fleet';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startHostProcess, stopAllHostProcesses } from '../physical/host-process.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import type { NatsServer } from '../nats/nats-server.js';
import { deviceId, gridStart } from './layout.js';

const COUNT = 50;
/** Simulated seconds per real second in the robot host: the robots move 4x faster than real. */
const SPEED = 4;
const ids = Array.from({ length: COUNT }, (_, i) => deviceId('r', i));

let server: NatsServer;
let manager: DeviceManager;

beforeAll(async () => {
  server = await startNatsServer();
  const host = startHostProcess('../../fleet/processes/fleet-gateways.ts', [
    server.url,
    'r',
    String(COUNT),
    String(SPEED),
    '10',
  ]);
  await host.waitFor((e) => e.event === 'serving', 50_000);
  manager = new DeviceManager({
    nats: { servers: server.url },
    telemetryRateHz: 1,
    offlineAfterMs: 4000,
    // "ghost" is configured but nobody serves it: it stays offline
    devices: [...ids, 'ghost'].map((id) => ({ type: 'nats', id })),
  });
  await manager.start();
}, 90_000);

afterAll(async () => {
  await manager?.stop();
  await stopAllHostProcesses();
  await stopAllNatsServers();
}, 30_000);

function codes(report: FleetReport): Record<string, string | undefined> {
  return Object.fromEntries(report.results.map((r) => [r.device, r.result.code]));
}

describe('a fleet of 50 simulated robots on NATS', () => {
  it('sees every served robot online and the one nobody serves offline', () => {
    const health = manager.health();
    expect(health.filter((h) => h.online).map((h) => h.device)).toEqual(ids);
    expect(health.find((h) => h.device === 'ghost')).toMatchObject({ online: false, ready: false });
  });

  it("moves all 50 in synchronized mode, with every robot's own result; the absent one fails alone", async () => {
    const report = await manager.fleet.synchronized(
      { kind: 'moveForward', distanceCm: 2 },
      { timeoutMs: 30_000 },
    );
    expect(report.succeeded).toEqual(ids);
    expect(report.failed).toEqual(['ghost']);
    const ghost = report.results.find((r) => r.device === 'ghost')?.result;
    expect(ghost).toMatchObject({
      code: 'NOT_CONNECTED',
      details: { device: 'ghost', offline: true },
    });
    // issued in the same tick: no robot waited for another to finish
    const issued = report.results.map((r) => r.issuedAt);
    expect(Math.max(...issued) - Math.min(...issued)).toBeLessThan(1000);
    const poses = await Promise.all(
      ids.map((id) => manager.createDeviceHAL(id).locomotion.getPose()),
    );
    poses.forEach((pose, i) => {
      expect(pose.position.x).toBeCloseTo(gridStart(i).x + 0.02, 3);
    });
  }, 60_000);

  it('keeps 49 followers in the grid formation while the leader drives 20 cm', async () => {
    const leader = ids[0]!;
    const start0 = gridStart(0);
    const formation = Object.fromEntries(
      ids.slice(1).map((id, k) => {
        const s = gridStart(k + 1);
        return [id, { x: s.x - start0.x, y: s.y - start0.y }];
      }),
    );
    const run = await manager.fleet.leaderFollower({
      leader,
      formation,
      periodMs: 250,
      toleranceM: 0.02,
      alignHeading: false,
      leaderStillMs: 1500,
      settleTimeoutMs: 60_000,
    });
    const moved = await manager.createDeviceHAL(leader).locomotion.moveForward(20);
    expect(moved.success).toBe(true);
    const report = await run.done;
    expect(report.reason).toBe('leader-stopped');
    expect(report.followers).toHaveLength(49);
    // Stated tolerance: every follower ends within 2 cm of its slot.
    for (const follower of report.followers) {
      expect(follower.errorM, follower.device).toBeLessThan(0.02);
    }
    expect(report.leaderPose?.x).toBeCloseTo(0.22, 2);
  }, 120_000);

  it('latches all 50 with the fleet e-stop, on the robots themselves, and resets them', async () => {
    const report = await manager.emergencyStop('fleet drill');
    expect(report.succeeded).toEqual([...ids, 'ghost']);
    for (const r of report.results.filter((x) => x.device !== 'ghost')) {
      expect(r.result.data).toMatchObject({ delivered: true });
    }
    // the absent robot's NatsHAL latches on this host and will latch the robot when it connects
    const ghost = report.results.find((r) => r.device === 'ghost')?.result;
    expect(ghost?.data).toMatchObject({ delivered: false });
    expect(manager.createDeviceHAL('ghost').safety.isEmergencyStopped()).toBe(true);
    expect(report.executionTime).toBeLessThan(10_000);
    // A second manager has no host-side latch: only the robots' own latch can refuse it.
    const other = new DeviceManager({
      nats: { servers: server.url },
      devices: ids.map((id) => ({ type: 'nats', id })),
    });
    try {
      await other.start();
      const refused = await other.fleet.synchronized({ kind: 'moveForward', distanceCm: 1 });
      expect(new Set(Object.values(codes(refused)))).toEqual(new Set(['EMERGENCY_STOPPED']));
      const reset = await manager.fleet.resetEmergencyStop();
      expect(reset.succeeded).toEqual(ids);
      // the absent robot cannot confirm a reset, so the fleet stays latched
      expect(reset.failed).toEqual(['ghost']);
      expect(manager.fleet.isEmergencyStopped()).toBe(true);
      await manager.unregister('ghost');
      expect((await manager.fleet.resetEmergencyStop()).success).toBe(true);
      expect(manager.fleet.isEmergencyStopped()).toBe(false);
      const moved = await other.fleet.synchronized({ kind: 'moveForward', distanceCm: 1 });
      expect(moved.success).toBe(true);
    } finally {
      await other.stop();
    }
  }, 90_000);
});
