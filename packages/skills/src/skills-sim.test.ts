// The skills over the simulator, guarded and leashed as `hal agent` runs them. Each skill's words
// and facts are checked against the simulator's truth (sim.robot, the world's objects), which the
// skills themselves never read: they see through captureFrame and getPose only.
import { guardHal } from '@hal/perception';
import { SimulationHAL, World } from '@hal/simulation';
import { createToolExecutor, halTools, toolBackedHal } from '@hal/tools';
import type { Leash, ToolResult } from '@hal/tools';
import { afterEach, describe, expect, it } from 'vitest';
import { createSkills } from './skill-set.js';
import { toolProfile } from './tool-profile.js';

let sim: SimulationHAL | undefined;
afterEach(async () => {
  await sim?.cleanup();
  sim = undefined;
});

const RED = '#d62828';
const BLUE = '#1d4ed8';

/** A red box ahead-left and a blue pillar behind-left of the robot, which starts at 0, 0 facing +x. */
const TWO_THINGS = () =>
  new World({
    map: {
      name: 'two things',
      obstacles: [
        { kind: 'box', x: 1.3, y: 0.3, width: 0.3, depth: 0.3, height: 0.3, color: RED },
        { kind: 'cylinder', x: -1.0, y: 0.8, radius: 0.1, height: 0.4, color: BLUE },
      ],
    },
  });

async function skillsIn(world: World, leash: Leash = {}) {
  sim = new SimulationHAL({ world });
  await sim.initialize();
  const guarded = guardHal(sim);
  const primitives = createToolExecutor(guarded, { leash, tools: halTools(guarded) });
  const hal = toolBackedHal(guarded, (call) => primitives.execute(call));
  const skills = createSkills(hal);
  const profile = toolProfile('skills', primitives, skills);
  const call = (name: string, args: Record<string, unknown> | string = {}) =>
    profile.execute({ name, arguments: args });
  return { sim, skills, profile, call };
}

const text = (r: ToolResult) => (r.content[0]?.type === 'text' ? r.content[0].text : '');
const facts = (r: ToolResult) => r.structured ?? {};
/** Distance from (x, y) to the surface of the 0.3 m red box at (1.3, 0.3). */
const toRedBox = (x: number, y: number) =>
  Math.hypot(Math.max(Math.abs(x - 1.3) - 0.15, 0), Math.max(Math.abs(y - 0.3) - 0.15, 0));

describe('skills in the simulator', () => {
  it('look names what is in view, where it is, and how far the floor is clear', async () => {
    const { call } = await skillsIn(TWO_THINGS());
    const look = await call('look');
    expect(look.isError).toBe(false);
    expect(text(look)).toMatch(/^I see the red box 1 1\.\d\d m away, 1\d° left\./);
    const [red, ...others] = facts(look)['objects'] as Array<Record<string, number | string>>;
    expect(others).toEqual([]); // the blue pillar is behind: not in view
    expect(red).toMatchObject({ id: 'red box 1', colour: 'red', kind: 'box' });
    // the truth: centre 1.33 m away, 13° left
    expect(Math.abs((red?.['distanceM'] as number) - Math.hypot(1.3, 0.3))).toBeLessThan(0.08);
    expect(Math.abs((red?.['bearingDeg'] as number) - 13)).toBeLessThanOrEqual(3);
    const clear = facts(look)['clear'] as Record<string, number>;
    // the box's near face is 1.15 m ahead, 0.15..0.45 m left: the left side is nearer than the right
    expect(clear['leftM']).toBeLessThan(clear['rightM'] ?? 0);
  });

  it(
    'finds a thing behind it by turning, faces it, and goes to a box, stopping before it',
    {
      timeout: 60_000,
    },
    async () => {
      const { call, sim } = await skillsIn(TWO_THINGS());
      const find = await call('find', { target: 'the blue pillar' });
      expect(facts(find)['outcome']).toBe('found');
      expect(text(find)).toMatch(/^Found the blue pillar 1 1\.\d\d m away, straight ahead\./);
      // it faces the pillar in truth: the bearing of (-1, 0.8) from where the robot is
      const r = sim.robot;
      const off = Math.atan2(0.8 - r.y, -1 - r.x) - r.yaw;
      expect(Math.abs(Math.atan2(Math.sin(off), Math.cos(off)))).toBeLessThan((4 * Math.PI) / 180);

      const go = await call('go_to', { target: 'red box' });
      expect(facts(go)['outcome'], text(go)).toBe('reached');
      expect(text(go)).toMatch(/^Reached the red box 1: stopped 0\.\d\d m from it/);
      const gap = toRedBox(sim.robot.x, sim.robot.y);
      expect(gap).toBeLessThanOrEqual(0.25);
      expect(gap).toBeGreaterThan(0.05); // beside it, not in it
    },
  );

  it('remembers what it saw and goes back to where it started', { timeout: 60_000 }, async () => {
    const { call, sim } = await skillsIn(TWO_THINGS());
    const none = await call('where_is', { target: 'red box' });
    expect(facts(none)['outcome']).toBe('not-found');
    expect(text(none)).toBe('I have not seen a red box yet.');
    await call('look');
    expect((await call('move', { cm: 30 })).isError).toBe(false);
    expect((await call('turn', { degrees: 180 })).isError).toBe(false);
    const where = await call('where_is', { target: 'red box' });
    expect(facts(where)['outcome']).toBe('found');
    const [red] = facts(where)['objects'] as Array<Record<string, number>>;
    // now behind the robot, which faces -x from (0.3, 0)
    expect(Math.abs(Math.abs(red?.['bearingDeg'] ?? 0) - 180)).toBeLessThan(20);
    const seen = await call('what_have_you_seen');
    expect(text(seen)).toMatch(/^I have seen 1 box: the red box 1 /);
    const back = await call('go_back');
    expect(facts(back)['outcome'], text(back)).toBe('reached');
    expect(Math.hypot(sim.robot.x, sim.robot.y)).toBeLessThan(0.04);
  });

  it('moves and turns by what it is told, in cm and degrees, and says what it did', async () => {
    const { call, sim } = await skillsIn(TWO_THINGS());
    const move = await call('move', { cm: 25 });
    expect(text(move)).toBe('Moved 25.0 cm forward.');
    expect(sim.robot.x).toBeCloseTo(0.25, 2);
    const back = await call('move', '{"cm": -10}');
    expect(text(back)).toBe('Moved 10.0 cm backward.');
    expect(sim.robot.x).toBeCloseTo(0.15, 2);
    const turn = await call('turn', { degrees: -90 });
    expect(text(turn)).toBe('Turned 90° right.');
    expect((sim.robot.yaw * 180) / Math.PI).toBeCloseTo(-90, 0);
    expect(facts(turn)['pose']).toEqual({ x: 0.15, y: 0, yawDeg: -90 });
  });

  it('is stopped by the guard before a wall, and says so', { timeout: 30_000 }, async () => {
    const world = new World({
      map: { name: 'wall', walls: [{ from: [0.8, -1], to: [0.8, 1], thickness: 0.05 }] },
    });
    const { call, sim } = await skillsIn(world);
    const move = await call('move', { cm: 150 });
    expect(facts(move)['outcome']).toBe('guard-stopped');
    expect(text(move)).toMatch(/^Stopped by the guard: something is ahead/);
    expect(move.isError).toBe(false);
    // the front (0.07 m ahead of the centre) is short of the wall's face at 0.775 m
    expect(sim.robot.x + 0.07).toBeLessThan(0.775);
    expect(sim.robot.x).toBeGreaterThan(0.4);
  });

  it('drives a distance longer than the leash allows in legs it allows, and says so', async () => {
    const { call, sim } = await skillsIn(TWO_THINGS(), { maxDistanceM: 0.3 });
    const move = await call('move', { cm: 50 });
    expect(move.isError).toBe(false);
    expect(text(move)).toBe(
      'Moved 50.0 cm forward in 2 legs (the leash allows at most 30 cm per motion).',
    );
    expect(sim.robot.x).toBeCloseTo(0.5, 2);
  });

  it('is refused by the geofence, nothing moved, and the refusal says why', async () => {
    const fence = { minX: -1, maxX: 0.2, minY: -1, maxY: 1 };
    const { call, sim } = await skillsIn(TWO_THINGS(), { geofence: fence });
    const move = await call('move', { cm: 50 });
    expect(move.isError).toBe(true);
    expect(move.code).toBe('LEASH_GEOFENCE');
    expect(facts(move)['outcome']).toBe('refused');
    expect(text(move)).toMatch(/^Refused, nothing moved: .*geofence/);
    expect(sim.robot.x).toBe(0);
  });

  it('does nothing while the e-stop is engaged, and says it is engaged', async () => {
    const { call, sim } = await skillsIn(TWO_THINGS());
    const estop = await call('emergency_stop', { reason: 'test' });
    expect(estop.isError).toBe(false);
    const move = await call('move', { cm: 20 });
    expect(move.code).toBe('EMERGENCY_STOPPED');
    expect(facts(move)['outcome']).toBe('estopped');
    const go = await call('go_to_point', { x: 0.5, y: 0 });
    expect(facts(go)['outcome']).toBe('estopped');
    expect(sim.robot.x).toBe(0);
  });

  it('refuses bad arguments and unknown tools with a typed error, and moves nothing', async () => {
    const { call, sim } = await skillsIn(TWO_THINGS());
    const cases: Array<[string, Record<string, unknown> | string, string]> = [
      ['move', { cm: Number.NaN }, 'INVALID_PARAMETER'],
      ['move', { cm: 0 }, 'INVALID_PARAMETER'],
      ['move', { cm: 9999 }, 'INVALID_PARAMETER'],
      ['move', { distance: 10 }, 'INVALID_PARAMETER'],
      ['turn', '{"degrees": 90', 'BAD_ARGUMENTS'],
      ['go_to', { target: 'red box', x: 1, y: 0 }, 'INVALID_PARAMETER'],
      ['go_to', { x: 1, y: 0 }, 'INVALID_PARAMETER'],
      ['go_to_point', { x: 1 }, 'INVALID_PARAMETER'],
      ['go_to_point', { x: 1, y: 0, withinCm: 5 }, 'INVALID_PARAMETER'],
      ['go_to', { target: 'red box', withinCm: 10 }, 'INVALID_PARAMETER'],
      ['go_to', { target: 'something nice' }, 'INVALID_PARAMETER'],
      ['find', {}, 'INVALID_PARAMETER'],
      ['move_forward', { distanceCm: 10 }, 'UNKNOWN_TOOL'],
    ];
    for (const [name, args, code] of cases) {
      const result = await call(name, args);
      expect(result.isError, `${name} ${JSON.stringify(args)}`).toBe(true);
      expect(result.code, `${name} ${JSON.stringify(args)}`).toBe(code);
    }
    expect(sim.robot.x).toBe(0);
    expect(sim.robot.yaw).toBe(0);
  });

  it(
    'says a thing is not here when it looked all round and saw none',
    { timeout: 30_000 },
    async () => {
      const { call } = await skillsIn(TWO_THINGS());
      const find = await call('find', { target: 'green box' });
      expect(facts(find)['outcome']).toBe('not-found');
      expect(text(find)).toBe('No green box in view from here (I looked all round).');
    },
  );
});

describe('tool profiles', () => {
  it('skills: the skills with the stop, the e-stop and its reset; primitives: the HAL tools; all: both', async () => {
    const { skills } = await skillsIn(TWO_THINGS());
    const primitives = createToolExecutor(sim!, {});
    const names = (p: 'skills' | 'primitives' | 'all') =>
      toolProfile(p, primitives, skills).tools.map((t) => t.name);
    expect(names('skills')).toEqual([
      'look',
      'find',
      'go_to',
      'go_to_point',
      'face',
      'explore',
      'where_is',
      'what_have_you_seen',
      'go_back',
      'move',
      'turn',
      'stop',
      'emergency_stop',
      'reset_emergency_stop',
    ]);
    expect(names('primitives')).toEqual(primitives.tools.map((t) => t.name));
    expect(names('all')).toEqual([
      ...skills.tools.map((t) => t.name),
      ...primitives.tools.map((t) => t.name),
    ]);
    const refused = await toolProfile('skills', primitives, skills).execute({
      name: 'move_forward',
      arguments: { distanceCm: 10 },
    });
    expect(refused.code).toBe('UNKNOWN_TOOL');
    expect(sim!.robot.x).toBe(0);
  });
});

describe('a stop interrupts the skills', () => {
  it('drops the calls queued before it: they start no motion', async () => {
    const { skills, sim } = await skillsIn(TWO_THINGS());
    const first = skills.execute({ name: 'move', arguments: { cm: 30 } });
    const second = skills.execute({ name: 'turn', arguments: { degrees: 90 } });
    skills.interrupt();
    for (const result of await Promise.all([first, second])) {
      expect(result.code).toBe('INTERRUPTED');
      expect(text(result)).toMatch(/^Stopped: a stop interrupted (move|turn)/);
    }
    expect(sim.robot.x).toBe(0);
    expect(sim.robot.yaw).toBe(0);
  });

  it('ends a skill under way before its next motion', async () => {
    sim = new SimulationHAL({ world: TWO_THINGS() });
    await sim.initialize();
    const robot = sim;
    // the first turn of the look all round waits until the test lets it go
    let release: () => void = () => undefined;
    const held = new Promise<void>((resolve) => (release = resolve));
    let turns = 0;
    const locomotion = new Proxy(robot.locomotion, {
      get(target, key) {
        if (key === 'rotate')
          return async (direction: 'left' | 'right', degrees: number) => {
            turns += 1;
            if (turns === 1) await held;
            return target.rotate(direction, degrees);
          };
        const value: unknown = Reflect.get(target, key);
        return typeof value === 'function' ? (value as () => unknown).bind(target) : value;
      },
    });
    const hal = new Proxy(robot, {
      get(target, key) {
        if (key === 'locomotion') return locomotion;
        const value: unknown = Reflect.get(target, key);
        return typeof value === 'function' ? (value as () => unknown).bind(target) : value;
      },
    });
    const skills = createSkills(hal);
    const look = skills.execute({ name: 'look', arguments: { around: true } });
    await expect.poll(() => turns).toBe(1);
    skills.interrupt();
    release();
    const result = await look;
    expect(result.code).toBe('INTERRUPTED');
    expect(turns).toBe(1); // the turn under way ended; no other started
  });
});
