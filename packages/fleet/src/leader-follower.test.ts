import { SimulationHAL, World } from '@hal/simulation';
import { angleDifference } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { Fleet } from './fleet.js';
import { formationOffsets } from './formation.js';
import type { FormationReport } from './leader-follower-options.js';
import { SteppedScheduler } from './scheduler.js';
import { simFleet, stepUntil } from './test-fleet.fixture.js';

/** A leader at the origin and followers placed roughly behind it, in one stepped world. */
async function formationWorld(followers: number) {
  const world = new World();
  const { members, hals } = await simFleet(followers + 1, { world, spacingM: 0.25 });
  const scheduler = new SteppedScheduler();
  const fleet = new Fleet(members, { scheduler });
  return { world, members, hals, scheduler, fleet };
}

describe('leader-follower mode (simulated time)', () => {
  it('brings followers to their slots around the leader after it moves, then ends', async () => {
    const { world, hals, scheduler, fleet } = await formationWorld(2);
    const offsets = formationOffsets('wedge', ['r1', 'r2'], 0.25);
    const formation = await fleet.leaderFollower({ leader: 'r0', formation: offsets });
    let report: FormationReport | undefined;
    void formation.done.then((r) => (report = r));
    let leaderDone = false;
    void hals[0]!.locomotion.moveTo(0.3, 0.2, 0).then((r) => {
      expect(r.success).toBe(true);
      leaderDone = true;
    });
    expect(await stepUntil(world, scheduler, () => report !== undefined, 180_000)).toBe(true);
    expect(leaderDone).toBe(true);
    expect(report?.reason).toBe('leader-stopped');
    const leader = await hals[0]!.locomotion.getPose();
    expect(leader.position.x).toBeCloseTo(0.3, 2);
    for (const follower of report?.followers ?? []) {
      expect(follower.errorM).toBeLessThan(0.03);
    }
    // each follower's slot is its offset turned by the leader's heading
    const yaw = leader.rotation.yaw;
    const r1 = await hals[1]!.locomotion.getPose();
    const o = offsets['r1']!;
    const slotX = leader.position.x + Math.cos(yaw) * o.x - Math.sin(yaw) * o.y;
    const slotY = leader.position.y + Math.sin(yaw) * o.x + Math.cos(yaw) * o.y;
    expect(Math.hypot(r1.position.x - slotX, r1.position.y - slotY)).toBeLessThan(0.03);
    expect(Math.abs(angleDifference(r1.rotation.yaw, yaw))).toBeLessThan((10 * Math.PI) / 180);
    expect(formation.running).toBe(false);
  });

  it('stops every follower at once on stop()', async () => {
    const { world, hals, scheduler, fleet } = await formationWorld(2);
    const formation = await fleet.leaderFollower({
      leader: 'r0',
      formation: formationOffsets('column', ['r1', 'r2'], 0.3),
    });
    void hals[0]!.locomotion.moveForward(20);
    await stepUntil(world, scheduler, () => hals[1]!.robot.running && hals[2]!.robot.running, 5000);
    expect(hals[1]!.robot.running).toBe(true);
    const report = await formation.stop();
    expect(report.reason).toBe('stopped');
    expect([hals[1]!.robot.running, hals[2]!.robot.running]).toEqual([false, false]);
  });

  it("ends and stops the followers when any member's e-stop latches", async () => {
    const { world, hals, scheduler, fleet } = await formationWorld(2);
    const formation = await fleet.leaderFollower({
      leader: 'r0',
      formation: formationOffsets('column', ['r1', 'r2'], 0.3),
    });
    void hals[0]!.locomotion.moveForward(20);
    await stepUntil(world, scheduler, () => hals[2]!.robot.running, 5000);
    await hals[1]!.safety.emergencyStop('bumped');
    let report: FormationReport | undefined;
    void formation.done.then((r) => (report = r));
    expect(await stepUntil(world, scheduler, () => report !== undefined, 2000)).toBe(true);
    expect(report).toMatchObject({ reason: 'estop', estopDevice: 'r1' });
    expect(hals[2]!.robot.running).toBe(false);
  });

  it('refuses a formation that names an unknown member, the leader as follower, or a bad offset', async () => {
    const { fleet } = await formationWorld(1);
    await expect(
      fleet.leaderFollower({ leader: 'r0', formation: { ghost: { x: -0.2, y: 0 } } }),
    ).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
    await expect(
      fleet.leaderFollower({ leader: 'r0', formation: { r0: { x: -0.2, y: 0 } } }),
    ).rejects.toThrow(/cannot follow itself/);
    await expect(
      fleet.leaderFollower({ leader: 'r0', formation: { r1: { x: Number.NaN, y: 0 } } }),
    ).rejects.toThrow(/finite metres/);
    await expect(
      fleet.leaderFollower({ leader: 'r0', formation: { r1: { x: -0.2, y: 0 } }, periodMs: -1 }),
    ).rejects.toThrow(/periodMs/);
    expect(fleet.formation).toBeUndefined();
  });
});

describe('leader-follower mode (fast-clock simulators, wall-clock fleet)', () => {
  it('ends once the followers settle after a leader move that finishes before the first tick', async () => {
    // the fast clock runs a whole motion inside the call: no tick ever sees the leader moving
    const world = new World();
    const hals = [0, -0.3].map(
      (x, i) =>
        new SimulationHAL({ world, clock: 'fast', deviceId: `f${i}`, start: { x, y: 0, yaw: 0 } }),
    );
    await Promise.all(hals.map((hal) => hal.initialize()));
    const fleet = new Fleet(hals.map((hal, i) => ({ id: `f${i}`, hal })));
    const formation = await fleet.leaderFollower({
      leader: 'f0',
      formation: formationOffsets('column', ['f1'], 0.3),
      settleTimeoutMs: 5000,
    });
    expect((await hals[0]!.locomotion.moveForward(10)).success).toBe(true);
    let giveUp = (): void => undefined;
    const late = new Promise<undefined>((resolve) => (giveUp = () => resolve(undefined)));
    const timer = setTimeout(() => giveUp(), 4000);
    const report = await Promise.race([formation.done, late]);
    clearTimeout(timer);
    if (report === undefined) await formation.stop();
    expect(report?.reason).toBe('leader-stopped');
    expect(report?.followers[0]?.errorM).toBeLessThan(0.03);
    await Promise.all(hals.map((hal) => hal.cleanup()));
  });
});
