import { describe, expect, it } from 'vitest';
import { OccupancyGrid } from './occupancy-grid.js';

describe('OccupancyGrid', () => {
  it('defaults to a 5 m x 5 m grid of 5 cm cells centred on the origin, all unknown', () => {
    const grid = new OccupancyGrid();
    expect(grid.spec).toEqual({
      width: 100,
      height: 100,
      resolutionM: 0.05,
      originX: -2.5,
      originY: -2.5,
    });
    expect(grid.counts()).toEqual({ unknown: 10_000, free: 0, occupied: 0 });
    expect(grid.stateAt(0, 0)).toBe('unknown');
    expect(grid.stateAt(9, 9)).toBe('unknown');
  });

  it('refuses a bad size, naming the option', () => {
    expect(() => new OccupancyGrid({ widthM: -1 })).toThrow('"widthM"');
    expect(() => new OccupancyGrid({ resolutionM: 0 })).toThrow('"resolutionM"');
    expect(() => new OccupancyGrid({ robotRadiusM: Number.NaN })).toThrow('"robotRadiusM"');
  });

  describe('#forgetWeakObstacles', () => {
    it('turns obstacles seen once or twice back to unknown, and keeps the well-seen and the mapped', () => {
      const grid = new OccupancyGrid();
      grid.seedFromMap({
        arena: { width: 5, height: 5 },
        obstacles: [{ kind: 'box', x: 1, y: 1, width: 0.1, depth: 0.1 }],
      });
      grid.addEvidence(10, 10, 0.85 + 0.2); // one hit on a seeded free cell: weak
      for (let k = 0; k < 5; k += 1) grid.addEvidence(20, 20, 0.85); // many hits: strong
      expect(grid.stateOf(10, 10)).toBe('occupied');
      expect(grid.forgetWeakObstacles()).toBe(1);
      expect(grid.stateOf(10, 10)).toBe('unknown');
      expect(grid.obstacles.isObstacle(10, 10)).toBe(false);
      expect(grid.stateOf(20, 20)).toBe('occupied');
      expect(grid.stateAt(1, 1)).toBe('occupied');
    });
  });

  describe('#markFree', () => {
    it('marks the footprint of the robot free', () => {
      const grid = new OccupancyGrid();
      grid.markFree(0, 0, 0.07);
      expect(grid.stateAt(0.02, 0.02)).toBe('free');
      expect(grid.stateAt(0.2, 0)).toBe('unknown');
    });
  });

  describe('#plan', () => {
    it('plans around a seeded obstacle with waypoints at cell centres', () => {
      const grid = new OccupancyGrid();
      grid.seedFromMap({
        arena: { width: 5, height: 5 },
        obstacles: [{ kind: 'box', x: 0, y: 0, width: 0.4, depth: 2 }],
      });
      const plan = grid.plan({ x: -1, y: 0 }, { x: 1, y: 0 });
      expect(plan.status).toBe('found');
      const last = plan.waypoints.at(-1);
      expect(last?.x).toBeCloseTo(1.025, 9);
      expect(last?.y).toBeCloseTo(0.025, 9);
      for (const p of plan.waypoints) {
        expect(((p.x + 2.5) / 0.05) % 1).toBeCloseTo(0.5, 6);
        expect(grid.isTraversable(p.x, p.y)).toBe(true);
      }
      expect(plan.lengthM).toBeGreaterThan(2);
      expect(plan.lengthM).toBeLessThanOrEqual(plan.costM + 1e-9);
      expect(grid.plan({ x: 0, y: 0 }, { x: 1, y: 0 }).status).toBe('start-blocked');
      expect(grid.plan({ x: -1, y: 0 }, { x: 9, y: 0 }).status).toBe('out-of-bounds');
    });
  });
});
