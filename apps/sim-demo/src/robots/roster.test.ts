import { World } from '@hal/simulation';
import type { FrameSource } from '@hal/simulation';
import { afterEach, describe, expect, it } from 'vitest';
import { MAX_ROBOTS } from './palette.js';
import { RobotRoster } from './roster.js';
import { selectedHal } from './selected-hal.js';

const noFrames: FrameSource = async () => 'data:image/jpeg;base64,';

/** The smallest distance between two robots' centres in the world, metres. */
function closestPair(world: World): number {
  let best = Number.POSITIVE_INFINITY;
  for (const a of world.robots) {
    for (const b of world.robots) {
      if (a !== b) best = Math.min(best, Math.hypot(a.x - b.x, a.y - b.y));
    }
  }
  return best;
}

describe('RobotRoster', () => {
  const worlds: World[] = [];
  afterEach(() => {
    for (const world of worlds.splice(0)) world.stopRealtime();
  });

  async function roster(map: 'obstacles' | 'maze' = 'obstacles'): Promise<RobotRoster> {
    const world = new World({ map });
    worlds.push(world);
    world.startRealtime({ speed: 1 });
    return RobotRoster.create({ world, frameSource: noFrames });
  }

  it('adds up to eight robots in one world, apart, each with its own HAL, colour and label', async () => {
    const r = await roster();
    while (r.robots.length < MAX_ROBOTS) await r.add();
    expect(r.world.robots.map((x) => x.id)).toEqual(r.robots.map((x) => x.id));
    expect(new Set(r.robots.map((x) => x.hal)).size).toBe(MAX_ROBOTS);
    expect(new Set(r.robots.map((x) => x.color)).size).toBe(MAX_ROBOTS);
    expect(r.robots.map((x) => x.label)).toEqual(['R1', 'R2', 'R3', 'R4', 'R5', 'R6', 'R7', 'R8']);
    expect(r.robots[0]?.hal.robot.x).toBe(-1.8); // the map's first start
    expect(closestPair(r.world)).toBeGreaterThan(2 * 0.07 + 0.05);
    await expect(r.add()).rejects.toMatchObject({ code: 'RANGE_EXCEEDED' });
    expect(r.world.robots).toHaveLength(MAX_ROBOTS);
  });

  it('keeps the last robot, and reuses a removed robot number', async () => {
    const r = await roster();
    await r.add();
    await r.add();
    r.select('robot-2');
    await r.remove('robot-2');
    expect(r.selected.id).toBe('robot-1');
    expect(r.world.robots.map((x) => x.id)).toEqual(['robot-1', 'robot-3']);
    expect((await r.add()).id).toBe('robot-2');
    await r.remove('robot-1');
    await r.remove('robot-2');
    await expect(r.remove('robot-3')).rejects.toMatchObject({ code: 'INVALID_PARAMETER' });
    expect(() => r.select('robot-9')).toThrow(/no robot "robot-9"/);
    expect(r.robots.map((x) => x.id)).toEqual(['robot-3']);
  });

  it('puts every robot at a separate free place again when the map changes', async () => {
    const r = await roster();
    for (let i = 0; i < 5; i += 1) await r.add();
    r.resetWorld('maze');
    expect(r.world.robots).toHaveLength(6);
    expect(closestPair(r.world)).toBeGreaterThan(2 * 0.07 + 0.05);
    for (const robot of r.world.robots)
      expect(r.world.contactAt(robot.x, robot.y, 0.07, robot)).toBeUndefined();
    // The HALs drive the re-created robots (they hold them by id).
    for (const robot of r.robots) expect(robot.hal.robot).toBe(r.world.robot(robot.id));
  });

  it('lets one HAL object drive whichever robot is selected', async () => {
    const r = await roster();
    await r.add();
    const hal = selectedHal(() => r.selected.hal);
    expect(hal.robot.id).toBe('robot-1');
    r.select('robot-2');
    expect(hal.robot.id).toBe('robot-2');
    expect(hal.getDeviceInfo().id).toBe('sim-robot-2');
    const result = await hal.safety.emergencyStop('test');
    expect(result.success).toBe(true);
    expect(r.robot('robot-2').hal.robot.emergencyStopped).toBe(true);
    expect(r.robot('robot-1').hal.robot.emergencyStopped).toBe(false);
  });
});
