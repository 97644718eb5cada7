import { describe, expect, it } from 'vitest';
import { worldToCell } from './geometry.js';
import { OccupancyGrid } from './occupancy-grid.js';

describe('OccupancyGrid', () => {
  describe('#integrateRay', () => {
    it('adds free evidence along the ray and occupied evidence where it ends', () => {
      const grid = new OccupancyGrid();
      grid.integrateRay(0.01, 0.01, 0, 1, true);
      expect(grid.stateAt(0.5, 0.01)).toBe('free');
      expect(grid.stateAt(0.98, 0.01)).toBe('free');
      expect(grid.stateAt(1.01, 0.01)).toBe('occupied');
      expect(grid.stateAt(1.2, 0.01)).toBe('unknown');
      expect(grid.stateAt(0.5, 0.2)).toBe('unknown');
      expect(grid.obstacles.isObstacle(70, 50)).toBe(true);
    });

    it('clears an obstacle that later rays pass through', () => {
      const grid = new OccupancyGrid();
      grid.integrateRay(0.01, 0.01, 0, 1, true);
      expect(grid.stateAt(1.01, 0.01)).toBe('occupied');
      for (let k = 0; k < 4; k += 1) grid.integrateRay(0.01, 0.01, 0, 1.5, false);
      expect(grid.stateAt(1.01, 0.01)).toBe('free');
      const cell = worldToCell(grid.spec, 1.01, 0.01);
      expect(grid.obstacles.isObstacle(cell?.cx ?? -1, cell?.cy ?? -1)).toBe(false);
    });
  });

  describe('#integrateRangeReadings', () => {
    it('places the front reading ahead, the left one at +y and the right one at -y (REP-103)', () => {
      const grid = new OccupancyGrid();
      grid.integrateRangeReadings(
        { x: 0.01, y: 0.01, yaw: 0 },
        { front: 0.5, left: 0.8, right: 2 },
        { maxRangeM: 2, originOffsetM: 0.07, rays: 5, fieldOfViewDeg: 20 },
      );
      expect(grid.stateAt(0.58, 0.01)).toBe('occupied');
      expect(grid.stateAt(0.3, 0.01)).toBe('free');
      expect(grid.stateAt(0.01, 0.88)).toBe('occupied');
      expect(grid.stateAt(0.01, -1.5)).toBe('free'); // right: nothing within range
      // The obstacle may be anywhere across the cone: the arc at the reading's distance is marked.
      expect(grid.stateAt(0.57, 0.09)).toBe('occupied');
      expect(grid.stateAt(0.57, -0.07)).toBe('occupied');
      expect(grid.stateAt(0.57, 0.2)).toBe('unknown');
    });

    it('turns the beams with the heading: facing +y, the front reading lands on +y', () => {
      const grid = new OccupancyGrid();
      grid.integrateRangeReadings(
        { x: 0.01, y: 0.01, yaw: Math.PI / 2 },
        { front: 0.5, left: 2, right: 2 },
      );
      expect(grid.stateAt(0.01, 0.58)).toBe('occupied');
      expect(grid.stateAt(-1, 0.01)).toBe('free'); // left of a robot facing +y is -x
    });

    it('marks only the unknown cells of the arc when the grid already explains the reading', () => {
      const grid = new OccupancyGrid();
      // A known obstacle ahead (0.57, 0) and, beside it on the arc, one free and one unknown cell.
      grid.setLogOdds(61, 50, 4);
      grid.setLogOdds(61, 51, -2);
      const sensors = { maxRangeM: 2, originOffsetM: 0.07, rays: 5, fieldOfViewDeg: 20 };
      grid.integrateRangeReadings(
        { x: 0.01, y: 0.01, yaw: 0 },
        { front: 0.5, left: 2, right: 2 },
        sensors,
      );
      expect(grid.stateOf(61, 50)).toBe('occupied');
      expect(grid.stateOf(61, 51)).toBe('free'); // known free stays free
      expect(grid.stateAt(0.57, -0.07)).toBe('occupied'); // unknown on the arc: suspect
    });

    it('ignores readings that are not finite numbers', () => {
      const grid = new OccupancyGrid();
      grid.integrateRangeReadings(
        { x: 0, y: 0, yaw: 0 },
        { front: Number.NaN, left: Infinity, right: -1 },
      );
      expect(grid.counts().unknown).toBe(10_000);
    });
  });
});
