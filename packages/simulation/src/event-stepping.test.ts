import { describe, expect, it } from 'vitest';
import type { BUILTIN_MAPS } from './maps/index.js';
import type { WorldMapInput } from './map.js';
import { SeededRandom } from './rng.js';
import { runTickStepping } from './robot/tick-stepping.fixture.js';
import type { TickCommand, TickResult, TickRobotSpec } from './robot/tick-stepping.fixture.js';
import { World } from './world.js';

/*
 * Event stepping against the 1 ms tick stepping it replaced (kept as a test fixture): the same
 * scenarios with walls, obstacles and other robots must end the same way. A motion ends with the
 * same outcome, touching the same thing; where the tick stepping found a contact only at the end
 * of the tick, the event stepping finds it at the step itself, so the two may differ by the steps
 * of one tick (at most 2 at 1024 steps/s) and by less than one tick in time. Forty robots are
 * enough for the world to use its index of robot positions.
 */

interface Scenario {
  name: string;
  map: WorldMapInput | keyof typeof BUILTIN_MAPS;
  robots: TickRobotSpec[];
  maxUs: number;
}

const R = 0.07;
const robot = (x: number, y: number, yaw: number, command: TickCommand): TickRobotSpec => ({
  start: { x, y, yaw },
  radius: R,
  command,
});
const drive = (left: number, right: number, durationMs?: number): TickCommand =>
  durationMs === undefined
    ? { kind: 'drive', left, right }
    : { kind: 'drive', left, right, durationMs };
const move = (left: number, right: number, speed = 1024): TickCommand => ({
  kind: 'move',
  left,
  right,
  speed,
});

/** Robots on random headings and wheel speeds among the obstacles (seeded), in rows. */
function crowd(count: number, columns: number): TickRobotSpec[] {
  const random = new SeededRandom(11);
  const specs: TickRobotSpec[] = [];
  for (let i = 0; i < count; i += 1) {
    const x = -2.2 + (i % columns) * (4.4 / columns) + 0.05;
    const y = -1.9 + Math.floor(i / columns) * 0.5;
    const left = 300 + Math.floor(random.next() * 724);
    const right = 300 + Math.floor(random.next() * 724);
    specs.push(robot(x, y, random.next() * 2 * Math.PI, drive(left, right, 20_000)));
  }
  return specs;
}

const SCENARIOS: Scenario[] = [
  {
    name: 'straight into the arena wall',
    map: 'empty',
    robots: [robot(0, 0, 0, drive(1024, 1024))],
    maxUs: 120e6,
  },
  {
    name: 'a move into a box',
    map: 'obstacles',
    robots: [robot(-1.8, 0, 0, move(30_000, 30_000))],
    maxUs: 60e6,
  },
  {
    name: 'an arc into a box at a slow speed',
    map: 'obstacles',
    robots: [robot(-1.8, -0.6, 0, move(26_000, 29_250, 300))],
    maxUs: 120e6,
  },
  {
    name: 'a diagonal drive into a corner of a box',
    map: 'obstacles',
    robots: [robot(-1.5, -0.8, 0.9, drive(700, 700))],
    maxUs: 60e6,
  },
  {
    name: 'a drive along a circle into a cylinder',
    map: { name: 'post', obstacles: [{ kind: 'cylinder', x: 0.6, y: 0.3, radius: 0.15 }] },
    robots: [robot(0, 0, 0, drive(800, 1024))],
    maxUs: 60e6,
  },
  {
    name: 'backwards away from a wall it touches, then a turn in place there',
    map: 'empty',
    robots: [robot(2.5 - R, 0, 0, move(-2000, -2000)), robot(-2.5 + R, 1, 0, move(-1706, 1706))],
    maxUs: 20e6,
  },
  {
    name: 'two robots head on',
    map: 'empty',
    robots: [robot(-0.5, 0.01, 0, drive(1024, 1024)), robot(0.5, 0, Math.PI, drive(900, 900))],
    maxUs: 30e6,
  },
  {
    name: 'one robot into another that stands still',
    map: 'empty',
    robots: [robot(-0.6, 0.05, 0, move(20_000, 20_000)), robot(0.4, 0, 1, drive(0, 1, 1))],
    maxUs: 30e6,
  },
  { name: 'twenty robots among obstacles', map: 'obstacles', robots: crowd(20, 5), maxUs: 25e6 },
  // Enough robots for the world to find neighbours through its index of robot positions.
  { name: 'forty robots among obstacles', map: 'obstacles', robots: crowd(40, 8), maxUs: 15e6 },
];

function runEvents(scenario: Scenario): TickResult[] {
  const world = new World({ map: scenario.map });
  const robots = scenario.robots.map((spec, i) =>
    world.addRobot({ id: `r${i}`, start: spec.start, radius: spec.radius }),
  );
  scenario.robots.forEach((spec, i) => {
    const r = robots[i]!;
    const c = spec.command;
    if (c.kind === 'move') r.moveSteps(c.left, c.right, c.speed);
    else r.drive(c.left, c.right, c.durationMs);
  });
  world.advanceUntil(() => robots.every((r) => !r.running), scenario.maxUs);
  return robots.map((r) => ({
    outcome: r.motion?.outcome === 'collision' ? 'collision' : r.running ? 'running' : 'done',
    endedUs: r.motion?.endedUs,
    doneLeft: r.motion?.doneLeft ?? 0,
    doneRight: r.motion?.doneRight ?? 0,
    x: r.x,
    y: r.y,
    yaw: r.yaw,
    contact: r.motion?.contact,
  }));
}

function solidsOfScenario(scenario: Scenario) {
  return new World({ map: scenario.map }).solids;
}

describe('event stepping against the 1 ms tick stepping it replaced', () => {
  it.each(SCENARIOS.map((s) => [s.name, s] as const))(
    'ends %s the same way: same outcome, same contact, within one tick',
    (_name, scenario) => {
      const before = runTickStepping(solidsOfScenario(scenario), scenario.robots, scenario.maxUs);
      const after = runEvents(scenario);
      let collisions = 0;
      before.forEach((old, i) => {
        const now = after[i]!;
        const where = `robot ${i}`;
        expect(now.outcome, where).toBe(old.outcome);
        if (old.outcome === 'collision') {
          collisions += 1;
          expect(now.contact?.role, where).toBe(old.contact?.role);
          expect(now.contact?.index, where).toBe(old.contact?.index);
          expect(Math.abs(now.contact!.point.x - old.contact!.point.x), where).toBeLessThan(2e-4);
          expect(Math.abs(now.contact!.point.y - old.contact!.point.y), where).toBeLessThan(2e-4);
          // Against a solid: the step the tick found blocked, or one of that tick's steps
          // after it. Against another robot the tick stepping saw the robots before this one
          // already moved and those after it not yet, so it erred by a tick either way.
          const low = old.contact?.role === 'robot' ? -2 : 0;
          for (const [a, b] of [
            [now.doneLeft, old.doneLeft],
            [now.doneRight, old.doneRight],
          ] as const) {
            expect(Math.abs(a) - Math.abs(b), where).toBeGreaterThanOrEqual(low);
            expect(Math.abs(a) - Math.abs(b), where).toBeLessThanOrEqual(2);
          }
          expect(Math.abs(now.endedUs! - old.endedUs!), where).toBeLessThan(low < 0 ? 2000 : 1000);
          expect(Math.hypot(now.x - old.x, now.y - old.y), where).toBeLessThan(2e-4);
          expect(Math.abs(now.yaw - old.yaw), where).toBeLessThan(1e-3);
        } else {
          expect([now.doneLeft, now.doneRight], where).toEqual([old.doneLeft, old.doneRight]);
          expect(now.endedUs, where).toBe(old.endedUs);
          expect(Math.hypot(now.x - old.x, now.y - old.y), where).toBeLessThan(1e-6);
          expect(Math.abs(now.yaw - old.yaw), where).toBeLessThan(1e-9);
        }
      });
      if (scenario.name !== 'backwards away from a wall it touches, then a turn in place there') {
        expect(collisions, 'the scenario has a collision').toBeGreaterThan(0);
      }
    },
    // the old 1 ms tick stepping of forty robots takes seconds of CPU, more on a loaded machine
    60_000,
  );
});
