import { describe, expect, it } from 'vitest';
import type { WorldMapInput } from './map.js';
import { groupHits, joinDistance } from './range-scan.js';
import type { RangeHit } from './range-scan.js';
import { scanAround } from './sensors.js';
import { World } from './world.js';

/** A 10 x 10 m arena (its walls out of the sensors' 2 m) with these obstacles. */
function arena(obstacles: WorldMapInput['obstacles'], walls: WorldMapInput['walls'] = []): World {
  return new World({
    map: { name: 'test', arena: { width: 10, height: 10 }, obstacles, walls },
  });
}

describe('scanAround', () => {
  it('reports the face the rays hit, not the centre of the box, as one obstacle', () => {
    const world = arena([{ kind: 'box', x: 1, y: 0, width: 0.2, depth: 0.2 }]);
    const robot = world.addRobot({ start: { x: 0, y: 0, yaw: 0 } });
    const scan = scanAround(world, robot, 'targeted');
    expect(scan.frame).toBe('odometry');
    expect(scan.objects).toHaveLength(1);
    const [seen] = scan.objects;
    expect(seen).toMatchObject({ id: 'seen-1', type: 'obstacle', sensor: 'range' });
    // the near face is at x = 0.9; the box's centre (1, 0) is nowhere in the answer
    expect(seen?.position.x).toBeCloseTo(0.9, 6);
    expect(Math.abs(seen?.position.y ?? 1)).toBeLessThan(0.02);
    expect(seen?.distanceM).toBeCloseTo(0.9 - 0.07, 6);
    expect(seen?.bearingDeg).toBeCloseTo(0, 0);
    expect(seen?.sizeM).toBeGreaterThan(0.1);
    expect(seen?.sizeM).toBeLessThan(0.3);
    expect(seen?.confidence).toBeGreaterThan(0.9);
    expect(scan.nearestObstacle).toBeCloseTo(0.83, 6);
    expect(scan.clearAhead).toBe(true);
  });

  it('places what it sees where the robot believes it is, not where the world has it', async () => {
    const world = new World({ map: { name: 'big', arena: { width: 10, height: 10 } } });
    const robot = world.addRobot({
      start: { x: 0, y: 0, yaw: 0 },
      bodyError: { wheelDiameterErrorPct: 5, odometryNoisePct: 5, seed: 7 },
    });
    for (const [l, r] of [
      [60, 60],
      [-10, 10],
      [60, 60],
      [10, -10],
      [50, 50],
    ] as const) {
      const { finished } = robot.moveCm(l, r);
      world.advanceUntil(() => !robot.running, 60_000_000);
      await finished;
    }
    const believed = robot.reportedPose;
    const truth = { x: robot.x, y: robot.y, yaw: robot.yaw };
    expect(Math.hypot(believed.x - truth.x, believed.y - truth.y)).toBeGreaterThan(0.02);
    // a pillar 0.8 m ahead of the robot's true body
    const pillar = {
      x: truth.x + 0.8 * Math.cos(truth.yaw),
      y: truth.y + 0.8 * Math.sin(truth.yaw),
    };
    const here = arena([{ kind: 'cylinder', x: pillar.x, y: pillar.y, radius: 0.05 }]);
    // the same body and odometry, in a world with the pillar: replay the same commands
    const twin = here.addRobot({
      start: { x: 0, y: 0, yaw: 0 },
      bodyError: { wheelDiameterErrorPct: 5, odometryNoisePct: 5, seed: 7 },
    });
    for (const [l, r] of [
      [60, 60],
      [-10, 10],
      [60, 60],
      [10, -10],
      [50, 50],
    ] as const) {
      const { finished } = twin.moveCm(l, r);
      here.advanceUntil(() => !twin.running, 60_000_000);
      await finished;
    }
    expect(twin.reportedPose).toEqual(believed);
    const scan = scanAround(here, twin, 'targeted');
    expect(scan.objects).toHaveLength(1);
    const seen = scan.objects[0]?.position ?? { x: NaN, y: NaN };
    // where the believed frame puts the pillar's near side: 0.75 m ahead of the believed pose
    const expected = {
      x: believed.x + 0.75 * Math.cos(believed.yaw),
      y: believed.y + 0.75 * Math.sin(believed.yaw),
    };
    expect(Math.hypot(seen.x - expected.x, seen.y - expected.y)).toBeLessThan(0.02);
    // and not where the world has it
    const nearSide = {
      x: truth.x + 0.75 * Math.cos(truth.yaw),
      y: truth.y + 0.75 * Math.sin(truth.yaw),
    };
    expect(Math.hypot(seen.x - nearSide.x, seen.y - nearSide.y)).toBeGreaterThan(0.02);
  });

  it('does not report what is out of range or hidden behind a wall', () => {
    const world = arena(
      [
        { kind: 'cylinder', x: 1.2, y: 0, radius: 0.05 }, // behind the wall
        { kind: 'cylinder', x: 0, y: 3, radius: 0.1 }, // 3 m away, out of the 2 m range
      ],
      [{ from: [0.8, -0.3], to: [0.8, 0.3] }],
    );
    const robot = world.addRobot({ start: { x: 0, y: 0, yaw: 0 } });
    const scan = scanAround(world, robot, 'full');
    expect(scan.objects).toHaveLength(1);
    const wall = scan.objects[0];
    expect(wall?.position.x).toBeCloseTo(0.775, 2);
    expect(Math.abs(wall?.bearingDeg ?? 90)).toBeLessThan(5);
    expect(scan.clearAhead).toBe(true);
    const empty = arena([{ kind: 'cylinder', x: 0, y: 3, radius: 0.1 }]);
    const alone = scanAround(empty, empty.addRobot(), 'full');
    expect(alone.objects).toEqual([]);
    expect(alone.nearestObstacle).toBeUndefined();
  });

  it('names objects seen-1, seen-2, ... by bearing from the right, whatever they are', () => {
    const world = arena([
      { kind: 'box', x: 0.2, y: 1, width: 0.2, depth: 0.2 }, // left
      { kind: 'cylinder', x: 0.2, y: -1, radius: 0.1 }, // right
      { kind: 'cylinder', x: -1, y: 0, radius: 0.1 }, // behind: across the sweep's two ends
    ]);
    const robot = world.addRobot({ start: { x: 0, y: 0, yaw: 0 } });
    world.addRobot({ id: 'other', start: { x: 1, y: 0, yaw: 0 } }); // ahead
    const scan = scanAround(world, robot, 'full');
    expect(scan.objects.map((o) => o.id)).toEqual(['seen-1', 'seen-2', 'seen-3', 'seen-4']);
    expect(new Set(scan.objects.map((o) => o.type))).toEqual(new Set(['obstacle']));
    const bearings = scan.objects.map((o) => o.bearingDeg ?? NaN);
    expect(bearings).toEqual([...bearings].sort((a, b) => a - b));
    expect(bearings[0]).toBeLessThan(-60); // the right pillar first
    expect(Math.abs(bearings[1] ?? 99)).toBeLessThan(3); // the robot ahead: just an obstacle
    expect(bearings[2]).toBeGreaterThan(60); // the left box
    expect(Math.abs(bearings[3] ?? 0)).toBeGreaterThan(170); // the pillar behind, reported once
    expect(JSON.stringify(scan)).not.toMatch(/other|robot|box|cylinder|wall/);
  });

  it('repeats its noisy readings with the same seed and not with another', () => {
    const scan = (seed: number) => {
      const world = new World({ map: 'obstacles', seed });
      const robot = world.addRobot();
      return scanAround(world, robot, 'full', { noiseSigma: 0.01 });
    };
    expect(scan(3)).toEqual(scan(3));
    expect(scan(3)).not.toEqual(scan(4));
  });
});

describe('groupHits', () => {
  const hit = (bearingDeg: number, rangeM: number): RangeHit => {
    const a = (bearingDeg * Math.PI) / 180;
    return {
      bearingDeg,
      rangeM,
      x: (rangeM + 0.07) * Math.cos(a),
      y: (rangeM + 0.07) * Math.sin(a),
    };
  };

  it('splits at a miss and at a jump in range, and joins a flat face', () => {
    const hits = [hit(0, 1), hit(2, 1.001), undefined, hit(6, 1), hit(8, 1.5), hit(10, 1.5)];
    const groups = groupHits(hits, 2, 0, 0.07, false);
    expect(groups.map((g) => g.map((h) => h.bearingDeg))).toEqual([[0, 2], [6], [8, 10]]);
  });

  it('joins a group across the ends of a full turn', () => {
    const hits = [hit(-180, 1), hit(-175, 1), undefined, hit(175, 1)];
    const groups = groupHits(hits, 5, 0, 0.07, true);
    expect(groups.map((g) => g.map((h) => h.bearingDeg))).toEqual([[175, -180, -175]]);
  });

  it('allows more room between hits the farther and noisier they are', () => {
    expect(joinDistance(2, 5, 0)).toBeGreaterThan(joinDistance(1, 5, 0));
    expect(joinDistance(1, 5, 0.01)).toBeCloseTo(joinDistance(1, 5, 0) + 0.03, 9);
  });
});
