import { describe, expect, it } from 'vitest';
import { readDistanceSensors, scanAround } from './sensors.js';
import { World } from './world.js';

describe('readDistanceSensors', () => {
  it('measures from the body edge to the walls: front, left (+y) and right (-y)', () => {
    const world = new World({ map: { name: 'box', arena: { width: 4, height: 3 } } });
    const robot = world.addRobot({ start: { x: 1, y: 0.5, yaw: 0 } });
    const d = readDistanceSensors(world, robot, { maxRange: 5, rays: 1 });
    expect(d.front).toBeCloseTo(2 - 1 - 0.07, 9);
    expect(d.left).toBeCloseTo(1.5 - 0.5 - 0.07, 9);
    expect(d.right).toBeCloseTo(1.5 + 0.5 - 0.07, 9);
    expect(d.source).toBe('simulation');
  });

  it('reads the maximum range when nothing is within it', () => {
    const world = new World();
    const robot = world.addRobot();
    expect(readDistanceSensors(world, robot, { maxRange: 1 }).front).toBe(1);
  });

  it('sees an obstacle anywhere in its field of view, not only on the axis', () => {
    const world = new World({
      map: {
        name: 'post',
        obstacles: [{ kind: 'cylinder', x: 1, y: 0.15, radius: 0.05 }],
      },
    });
    const robot = world.addRobot();
    const narrow = readDistanceSensors(world, robot, { rays: 1 }).front;
    const wide = readDistanceSensors(world, robot, { fieldOfViewDeg: 25, rays: 9 }).front;
    expect(narrow).toBe(2);
    expect(wide).toBeLessThan(1);
  });

  it('adds seeded noise: the same seed gives the same readings, another seed others', () => {
    const read = (seed: number) => {
      const world = new World({ seed });
      const robot = world.addRobot({ start: { x: 1.5, y: 0, yaw: 0 } });
      return readDistanceSensors(world, robot, { noiseSigma: 0.01 }).front;
    };
    expect(read(3)).toBe(read(3));
    expect(read(3)).not.toBe(read(4));
  });
});

describe('scanAround', () => {
  it('reports what the range sensor sees once each, with no names from the world', () => {
    const world = new World({ map: 'obstacles' });
    const robot = world.addRobot();
    const scan = scanAround(world, robot, 'full');
    const ids = scan.objects.map((o) => o.id);
    expect(scan.objects.length).toBeGreaterThan(0);
    expect(new Set(ids).size).toBe(ids.length);
    for (const [i, o] of scan.objects.entries()) {
      expect(o.id).toBe(`seen-${i + 1}`);
      expect(o.type).toBe('obstacle');
      expect(o.distanceM).toBeLessThan(2);
    }
    expect(scan.clearAhead).toBe(true);
    expect(scan.nearestObstacle).toBeGreaterThan(0);
  });
});
