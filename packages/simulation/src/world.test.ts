import { isHalError } from '@hal/types';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { parseMap } from './map.js';
import { BUILTIN_MAPS } from './maps/index.js';
import { World } from './world.js';

describe('parseMap', () => {
  it('fills defaults: a 5 m x 5 m arena and a start at the origin', () => {
    const map = parseMap({ name: 'bare' });
    expect(map.arena).toEqual({ width: 5, height: 5, wallHeight: 0.3 });
    expect(map.starts).toEqual([{ x: 0, y: 0, yaw: 0 }]);
  });

  it('refuses a diagonal wall with INVALID_PARAMETER naming it', () => {
    let error: unknown;
    try {
      parseMap({ name: 'bad', walls: [{ from: [0, 0], to: [1, 1] }] });
    } catch (e) {
      error = e;
    }
    expect(isHalError(error) && error.code).toBe('INVALID_PARAMETER');
    expect(String(error)).toContain('walls.0');
  });

  it('ships empty, obstacles, maze and room, each a valid map that survives a JSON round trip', () => {
    expect(Object.keys(BUILTIN_MAPS).sort()).toEqual(['empty', 'maze', 'obstacles', 'room']);
    for (const map of Object.values(BUILTIN_MAPS)) {
      expect(parseMap(JSON.parse(JSON.stringify(map)))).toEqual(map);
    }
  });

  it('starts every robot of every built-in map clear of walls and obstacles', () => {
    for (const name of Object.keys(BUILTIN_MAPS) as Array<keyof typeof BUILTIN_MAPS>) {
      const world = new World({ map: name });
      for (const start of world.map.starts) {
        expect(world.contactAt(start.x, start.y, 0.07), `${name} ${JSON.stringify(start)}`).toBe(
          undefined,
        );
      }
    }
  });
});

describe('World', () => {
  afterEach(() => {
    vi.useRealTimers();
  });

  it('keeps stepping, calls the other listeners and logs the error when a listener throws', () => {
    const entries: Array<{
      level: string;
      namespace: string;
      fields: Record<string, unknown> | undefined;
    }> = [];
    const world = new World({
      logger: {
        log: (level, namespace, _message, fields) => entries.push({ level, namespace, fields }),
      },
    });
    const ticks: number[] = [];
    world.events.on('tick', () => {
      throw new Error('broken listener');
    });
    world.events.on('tick', (t) => ticks.push(t));
    expect(() => world.step()).not.toThrow();
    world.step();
    expect(ticks).toEqual([1000, 2000]);
    expect(entries).toHaveLength(2);
    expect(entries[0]).toMatchObject({
      level: 'error',
      namespace: 'hal:simulation:world',
      fields: { event: 'tick', error: 'broken listener' },
    });
  });

  it('stops a robot at the arena wall and reports the contact point', () => {
    const world = new World();
    const robot = world.addRobot();
    const contacts: unknown[] = [];
    world.events.on('collision', (c) => contacts.push(c));
    robot.drive(1024, 1024);
    world.advanceUntil(() => !robot.running, 120_000_000);
    expect(robot.motion?.outcome).toBe('collision');
    expect(robot.motion?.contact?.role).toBe('arena');
    expect(robot.motion?.contact?.point.x).toBeCloseTo(2.5, 6);
    expect(robot.x + robot.radius).toBeLessThanOrEqual(2.5);
    expect(robot.x + robot.radius).toBeGreaterThan(2.499);
    expect(contacts).toHaveLength(1);
  });

  it('lets a robot touching a wall turn in place and drive away from it', () => {
    const world = new World();
    const robot = world.addRobot({ start: { x: 2.5 - 0.07, y: 0, yaw: 0 } });
    robot.rotateDeg(180);
    world.advanceUntil(() => !robot.running, 10_000_000);
    expect(robot.motion?.outcome).toBe('done');
    robot.moveCm(10, 10);
    world.advanceUntil(() => !robot.running, 10_000_000);
    expect(robot.motion?.outcome).toBe('done');
    expect(robot.x).toBeCloseTo(2.33, 2);
  });

  it('stops robots that drive into each other', () => {
    const world = new World();
    const a = world.addRobot({ start: { x: -0.3, y: 0, yaw: 0 } });
    const b = world.addRobot({ start: { x: 0.3, y: 0, yaw: Math.PI } });
    a.drive(1024, 1024);
    b.drive(1024, 1024);
    world.advanceUntil(() => !a.running && !b.running, 30_000_000);
    expect(a.motion?.outcome).toBe('collision');
    expect(b.motion?.outcome).toBe('collision');
    expect(b.x - a.x).toBeGreaterThanOrEqual(0.14 - 1e-9);
  });

  it('is deterministic: the same seed and commands give the same state', () => {
    const run = () => {
      const world = new World({ map: 'obstacles', seed: 7 });
      const robot = world.addRobot();
      robot.drive(900, 1024);
      world.advance(20_000_000);
      return [robot.x, robot.y, robot.yaw, robot.leftSteps, world.random.next()];
    };
    expect(run()).toEqual(run());
  });

  it('puts robots back at their starts when the map changes', () => {
    const world = new World();
    world.addRobot({ id: 'a' });
    world.robot('a').moveCm(10, 10);
    world.advance(5_000_000);
    world.setMap('maze');
    const start = BUILTIN_MAPS.maze.starts[0];
    expect([world.robot('a').x, world.robot('a').y]).toEqual([start?.x, start?.y]);
  });

  it('runs against the wall clock at the requested speed with startRealtime', () => {
    vi.useFakeTimers();
    let wall = 0;
    const world = new World();
    world.startRealtime({ speed: 4, intervalMs: 10, now: () => wall });
    for (let i = 0; i < 10; i += 1) {
      wall += 10;
      vi.advanceTimersByTime(10);
    }
    world.stopRealtime();
    expect(world.nowUs).toBe(400_000);
    expect(world.realtimeSpeed).toBe(0);
  });
});

describe('World event stepping', () => {
  const scenario = () => {
    const world = new World({ map: 'obstacles' });
    const a = world.addRobot({ start: { x: -2, y: -2, yaw: 0.4 } });
    const b = world.addRobot({ start: { x: 1.9, y: 1.9, yaw: -2.5 } });
    a.drive(1024, 700, 12_000);
    b.moveSteps(9000, 8000, 900);
    return { world, a, b };
  };
  const state = (w: ReturnType<typeof scenario>) =>
    [w.a, w.b].map((r) => [r.x, r.y, r.yaw, r.leftSteps, r.rightSteps, r.motion?.endedUs]);

  it('ends in the same state, bit for bit, however the clock is advanced and whoever looks meanwhile', () => {
    const once = scenario();
    once.world.advance(15_000_000);
    const ticks = scenario();
    for (let i = 0; i < 15_000; i += 1) ticks.world.step();
    const watched = scenario();
    for (let i = 0; i < 1500; i += 1) {
      watched.world.advance(10_000);
      expect(watched.a.x + watched.b.y).not.toBeNaN(); // reads catch the robots up
    }
    expect(state(ticks)).toEqual(state(once));
    expect(state(watched)).toEqual(state(once));
  });

  it('checks for contact only near something: a few times, not at every step, in open space', () => {
    const world = new World({ map: { name: 'open', arena: { width: 20, height: 20 } } });
    const robot = world.addRobot();
    const contactAt = vi.spyOn(world, 'contactAt');
    robot.drive(1024, 1024, 20_000);
    world.advance(21_000_000);
    expect(robot.motion?.outcome).toBe('done');
    expect(Math.abs(robot.leftSteps)).toBeGreaterThan(19_000);
    expect(contactAt.mock.calls.length).toBeGreaterThan(0);
    expect(contactAt.mock.calls.length).toBeLessThan(60);
  });

  it('sees a robot coming that keeps its speed after set_config lowered the limit', () => {
    const world = new World();
    const mover = world.addRobot({ start: { x: -1, y: 0, yaw: 0 } });
    const still = world.addRobot({ start: { x: 0, y: 0, yaw: 0 } });
    still.setConfig({ maxSpeedStepsPerS: 1 });
    mover.drive(1024, 1024);
    world.advance(500_000);
    mover.setConfig({ maxSpeedStepsPerS: 1 }); // applies to the next motion: this one goes on
    world.advanceUntil(() => !mover.running, 60_000_000);
    expect(mover.motion?.outcome).toBe('collision');
    expect(still.x - mover.x).toBeGreaterThanOrEqual(0.14 - 1e-9);
  });

  it('sees a robot added in the way of one already moving', () => {
    const world = new World();
    const mover = world.addRobot({ start: { x: -1, y: 0, yaw: 0 } });
    mover.drive(1024, 1024);
    world.advance(2_000_000);
    world.addRobot({ id: 'late', start: { x: 0, y: 0, yaw: 0 } });
    world.advanceUntil(() => !mover.running, 60_000_000);
    expect(mover.motion?.outcome).toBe('collision');
    expect(mover.motion?.contact?.robotId).toBe('late');
    expect(world.robot('late').x - mover.x).toBeGreaterThanOrEqual(0.14 - 1e-9);
  });
});
