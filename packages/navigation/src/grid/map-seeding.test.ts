import { describe, expect, it } from 'vitest';
import { boxMap } from './known-map.fixture.js';
import { OccupancyGrid } from './occupancy-grid.js';

describe('OccupancyGrid', () => {
  describe('#seedFromMap', () => {
    it('marks walls, boxes, cylinders and the outside of the arena occupied, the rest free', () => {
      const grid = new OccupancyGrid();
      grid.seedFromMap(boxMap);
      expect(grid.stateAt(1, 1)).toBe('occupied');
      expect(grid.stateAt(1.15, 1.05)).toBe('occupied');
      expect(grid.stateAt(1.3, 1)).toBe('free');
      expect(grid.stateAt(-1, 1.15)).toBe('occupied');
      expect(grid.stateAt(-1, 1.3)).toBe('free');
      expect(grid.stateAt(0.02, -1.5)).toBe('occupied');
      expect(grid.stateAt(2.2, 0)).toBe('occupied'); // outside the 4 m arena
      expect(grid.stateAt(0, 0)).toBe('free');
      expect(grid.counts().unknown).toBe(0);
      // The planner's layer follows: the robot's centre keeps radius + clearance away.
      expect(grid.isTraversable(1, 0.8)).toBe(false);
      expect(grid.isTraversable(1, 0.7)).toBe(true);
      expect(grid.isTraversable(1.9, 0)).toBe(false);
    });

    it('sizes a grid to the arena of a map with OccupancyGrid.fromMap', () => {
      const grid = OccupancyGrid.fromMap(
        {
          arena: { width: 3, height: 2 },
          obstacles: [{ kind: 'cylinder', x: 0, y: 0, radius: 0.1 }],
        },
        { resolutionM: 0.1, marginM: 0.5 },
      );
      expect(grid.spec).toMatchObject({ width: 40, height: 30, originX: -2, originY: -1.5 });
      expect(grid.stateAt(0, 0)).toBe('occupied');
      expect(grid.stateAt(1.8, 0)).toBe('occupied'); // in the margin, outside the arena
      expect(grid.stateAt(1, 0.5)).toBe('free');
    });

    it('leaves open space unknown when told the map shows obstacles only', () => {
      const grid = new OccupancyGrid();
      grid.seedFromMap(boxMap, { freeSpace: false });
      expect(grid.stateAt(0, 0)).toBe('unknown');
      expect(grid.stateAt(1, 1)).toBe('occupied');
    });
  });
});
