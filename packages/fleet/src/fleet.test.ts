import { describe, expect, it } from 'vitest';
import { Fleet } from './fleet.js';
import { SteppedScheduler } from './scheduler.js';
import { flush, hangingMember, simFleet, stepUntil } from './test-fleet.fixture.js';

describe('Fleet', () => {
  describe('synchronized mode', () => {
    it('issues the command to every member in the same tick, before any has finished', async () => {
      const { world, members, hals } = await simFleet(3);
      const fleet = new Fleet(members);
      const pending = fleet.synchronized({ kind: 'moveForward', distanceCm: 5 });
      await flush();
      // nobody has stepped the world: every robot started at simulated time 0
      expect(hals.map((h) => h.robot.running)).toEqual([true, true, true]);
      expect(hals.map((h) => h.robot.motion?.startedUs)).toEqual([0, 0, 0]);
      const scheduler = new SteppedScheduler();
      let report: Awaited<typeof pending> | undefined;
      void pending.then((r) => (report = r));
      expect(await stepUntil(world, scheduler, () => report !== undefined, 10_000)).toBe(true);
      expect(report?.success).toBe(true);
      expect(report?.succeeded).toEqual(['r0', 'r1', 'r2']);
      for (const hal of hals) {
        expect((await hal.locomotion.getPose()).position.x).toBeCloseTo(0.05, 3);
      }
    });

    it("reports every member's own result: an e-stopped member fails alone", async () => {
      const { world, members, hals } = await simFleet(3);
      await hals[1]?.safety.emergencyStop('test');
      const fleet = new Fleet(members);
      const pending = fleet.synchronized({ kind: 'moveForward', distanceCm: 2 });
      let done = false;
      void pending.then(() => (done = true));
      await stepUntil(world, new SteppedScheduler(), () => done, 10_000);
      const report = await pending;
      expect(report.success).toBe(false);
      expect(report.failed).toEqual(['r1']);
      expect(report.succeeded).toEqual(['r0', 'r2']);
      expect(report.results[1]?.result.code).toBe('EMERGENCY_STOPPED');
      expect(report.results[0]?.result.success).toBe(true);
    });

    it('gives a member that never answers TIMEOUT without holding back the others', async () => {
      const { members } = await simFleet(2);
      const stuck = hangingMember('stuck', members[0]!.hal, 'moveForward');
      const fleet = new Fleet([stuck, members[1]!]);
      const report = await fleet.synchronized({ kind: 'stop' }, { timeoutMs: 200 });
      expect(report.success).toBe(true);
      const moving = await fleet.synchronized(
        (hal, device) =>
          device === 'stuck' ? hal.locomotion.moveForward(1) : hal.locomotion.stop(),
        { timeoutMs: 200 },
      );
      expect(moving.results.map((r) => r.result.code)).toEqual(['TIMEOUT', undefined]);
      expect(moving.results[0]?.result.details).toMatchObject({ device: 'stuck', timeoutMs: 200 });
      expect(moving.executionTime).toBeLessThan(5000);
    });

    it('refuses a malformed command or an unknown device before anything moves', async () => {
      const { members, hals } = await simFleet(2);
      const fleet = new Fleet(members);
      await expect(
        fleet.synchronized({ kind: 'moveForward', distanceCm: 'far' } as never),
      ).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
      await expect(fleet.synchronized({ kind: 'fly' } as never)).rejects.toMatchObject({
        code: 'INVALID_PARAMETER',
      });
      await expect(
        fleet.synchronized({ kind: 'stop' }, { devices: ['r0', 'ghost'] }),
      ).rejects.toMatchObject({ code: 'INVALID_PARAMETER', details: { unknown: ['ghost'] } });
      await expect(
        fleet.synchronized({ kind: 'stop' }, { timeoutMs: Number.NaN }),
      ).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
      expect(hals.map((h) => h.robot.running)).toEqual([false, false]);
    });

    it('passes out-of-range parameters to each HAL, which refuses them with its own code', async () => {
      const { members } = await simFleet(2);
      const report = await new Fleet(members).synchronized({ kind: 'drive', left: 999, right: 0 });
      expect(report.results.map((r) => r.result.code)).toEqual([
        'RANGE_EXCEEDED',
        'RANGE_EXCEEDED',
      ]);
    });
  });

  describe('independent mode', () => {
    it('routes a call to one member only', async () => {
      const { members, hals } = await simFleet(2);
      const fleet = new Fleet(members);
      const result = await fleet.independent('r1', { kind: 'drive', left: 100, right: 100 });
      expect(result.device).toBe('r1');
      expect(result.result.success).toBe(true);
      expect(hals.map((h) => h.robot.running)).toEqual([false, true]);
      expect(fleet.hal('r0')).toBe(hals[0]);
      expect(() => fleet.hal('nobody')).toThrow(/no fleet member "nobody"/);
    });

    it('refuses a duplicate or malformed device id', async () => {
      const { members } = await simFleet(1);
      const fleet = new Fleet(members);
      expect(() => fleet.add(members[0]!)).toThrow(/already has a member "r0"/);
      expect(() => fleet.add({ id: 'a b', hal: members[0]!.hal })).toThrow(/device ids/);
    });
  });

  describe('fleet e-stop', () => {
    it('latches every member at once and never waits on a member that does not answer', async () => {
      const { members, hals } = await simFleet(3);
      const slow = hangingMember('slow', hals[2]!, 'emergencyStop');
      const fleet = new Fleet([members[0]!, members[1]!, slow], { estopTimeoutMs: 150 });
      await fleet.synchronized({ kind: 'drive', left: 200, right: 200 });
      const report = await fleet.emergencyStop('drill');
      expect(fleet.isEmergencyStopped()).toBe(true);
      expect(report.succeeded).toEqual(['r0', 'r1']);
      expect(report.results[2]?.result.code).toBe('TIMEOUT');
      expect(report.executionTime).toBeLessThan(5000);
      expect(hals.slice(0, 2).map((h) => h.safety.isEmergencyStopped())).toEqual([true, true]);
      expect(hals.slice(0, 2).map((h) => h.robot.running)).toEqual([false, false]);
    });

    it('refuses fleet commands while latched (stop still allowed) until reset', async () => {
      const { members, hals } = await simFleet(2);
      const fleet = new Fleet(members);
      await fleet.emergencyStop();
      const refused = await fleet.synchronized({ kind: 'drive', left: 50, right: 50 });
      expect(refused.results.map((r) => r.result.code)).toEqual([
        'EMERGENCY_STOPPED',
        'EMERGENCY_STOPPED',
      ]);
      expect((await fleet.synchronized({ kind: 'stop' })).success).toBe(true);
      await expect(
        fleet.leaderFollower({ leader: 'r0', formation: { r1: { x: -0.2, y: 0 } } }),
      ).rejects.toMatchObject({ code: 'EMERGENCY_STOPPED' });
      const reset = await fleet.resetEmergencyStop();
      expect(reset.success).toBe(true);
      expect(fleet.isEmergencyStopped()).toBe(false);
      expect(hals.map((h) => h.safety.isEmergencyStopped())).toEqual([false, false]);
      expect((await fleet.synchronized({ kind: 'drive', left: 50, right: 50 })).success).toBe(true);
    });
  });
});
