import { formationOffsets } from '@hal/fleet';
import { World } from '@hal/simulation';
import type { FrameSource } from '@hal/simulation';
import { afterEach, describe, expect, it } from 'vitest';
import { RobotRoster } from '../robots/roster.js';
import { DemoFleet } from './demo-fleet.js';

const noFrames: FrameSource = async () => 'data:image/jpeg;base64,';

/** Resolves once `done()` is true, checking every 20 ms; rejects after `timeoutMs`. */
async function until(done: () => boolean, timeoutMs: number): Promise<void> {
  const end = Date.now() + timeoutMs;
  while (!done()) {
    if (Date.now() > end) throw new Error(`not done within ${timeoutMs} ms`);
    await new Promise((r) => setTimeout(r, 20));
  }
}

describe('DemoFleet', () => {
  const worlds: World[] = [];
  afterEach(() => {
    for (const world of worlds.splice(0)) world.stopRealtime();
  });

  async function fourRobots(): Promise<{ world: World; roster: RobotRoster; demo: DemoFleet }> {
    const world = new World({ map: 'empty' });
    worlds.push(world);
    // 20x real time, as the demo can run: a wedge gathers in well under a second.
    world.startRealtime({ speed: 20 });
    const roster = await RobotRoster.create({ world, frameSource: noFrames });
    for (let i = 0; i < 3; i += 1) await roster.add();
    return { world, roster, demo: new DemoFleet(roster) };
  }

  it('gathers the followers in a wedge behind the leader, the real-time world running', async () => {
    const { world, demo } = await fourRobots();
    const formation = await demo.fleet.leaderFollower({
      leader: 'robot-1',
      formation: formationOffsets('wedge', ['robot-2', 'robot-3', 'robot-4'], 0.35),
      stopWhenLeaderStops: false,
    });
    const errors = () =>
      Object.entries(formation.slots()).map(([id, slot]) => {
        const r = world.robot(id);
        return Math.hypot(r.x - slot.x, r.y - slot.y);
      });
    // Generous: about 0.5 s alone, much more on a loaded machine.
    await until(() => errors().length === 3 && errors().every((e) => e < 0.06), 60_000);
    const report = await formation.stop();
    expect(report.reason).toBe('stopped');
    expect(report.followers.map((f) => f.device)).toEqual(['robot-2', 'robot-3', 'robot-4']);
  }, 90_000);

  it('follows the roster: a removed robot leaves the fleet and a running formation stops', async () => {
    const { roster, demo } = await fourRobots();
    const formation = await demo.fleet.leaderFollower({
      leader: 'robot-1',
      formation: formationOffsets('line', ['robot-2', 'robot-3', 'robot-4'], 0.35),
    });
    await roster.remove('robot-3');
    demo.sync();
    expect(demo.fleet.devices).toEqual(['robot-1', 'robot-2', 'robot-4']);
    expect((await formation.done).reason).toBe('stopped');
    const added = await roster.add();
    demo.sync();
    expect(demo.fleet.devices).toEqual(['robot-1', 'robot-2', 'robot-4', added.id]);
  });

  it('stops a running formation when the map changes', async () => {
    const { roster, demo } = await fourRobots();
    const formation = await demo.fleet.leaderFollower({
      leader: 'robot-1',
      formation: formationOffsets('column', ['robot-2', 'robot-3', 'robot-4'], 0.35),
    });
    roster.resetWorld('obstacles');
    expect(formation.running).toBe(false);
    expect((await formation.done).reason).toBe('stopped');
    expect(demo.fleet.formation).toBeUndefined();
  });
});
