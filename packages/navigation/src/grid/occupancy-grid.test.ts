import jpeg from 'jpeg-js';
import { describe, expect, it } from 'vitest';
import { worldToCell } from './geometry.js';
import { gridImageDataUrl, renderGridImage } from './image.js';
import { OccupancyGrid } from './occupancy-grid.js';
import { traverseCells } from './raycast.js';
import { describeWorld } from './summary.js';

const boxMap = {
  arena: { width: 4, height: 4 },
  walls: [{ from: [0, -2] as [number, number], to: [0, -1] as [number, number], thickness: 0.1 }],
  obstacles: [
    { kind: 'box' as const, x: 1, y: 1, width: 0.4, depth: 0.2 },
    { kind: 'cylinder' as const, x: -1, y: 1, radius: 0.2 },
  ],
};

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

describe('traverseCells', () => {
  it('visits every cell of a diagonal ray in order and stops in the end cell', () => {
    const spec = { width: 10, height: 10, resolutionM: 1, originX: 0, originY: 0 };
    const cells: string[] = [];
    traverseCells(spec, 0.5, 0.5, 3.2, 1.7, (cx, cy) => {
      cells.push(`${cx},${cy}`);
    });
    expect(cells[0]).toBe('0,0');
    expect(cells.at(-1)).toBe('3,1');
    expect(cells).toHaveLength(5);
  });

  it('clips a ray that starts outside the grid', () => {
    const spec = { width: 4, height: 4, resolutionM: 1, originX: 0, originY: 0 };
    const cells: string[] = [];
    traverseCells(spec, -3, 1.5, 2.5, 1.5, (cx, cy) => {
      cells.push(`${cx},${cy}`);
    });
    expect(cells).toEqual(['0,1', '1,1', '2,1']);
    const none: string[] = [];
    traverseCells(spec, -3, -3, -1, -1, (cx, cy) => {
      none.push(`${cx},${cy}`);
    });
    expect(none).toEqual([]);
  });
});

describe('describeWorld', () => {
  it('summarises the grid, the pose, the goal and a coarse map for an LLM', () => {
    const grid = new OccupancyGrid();
    grid.seedFromMap(boxMap);
    const text = describeWorld(grid, {
      pose: { x: 0, y: 0, yaw: Math.PI / 2 },
      goal: { x: 1, y: 0 },
      readings: { front: 0.9, left: 2, right: 1.2 },
    });
    expect(text).toContain('Robot: at (0.00, 0.00) m, heading 90 deg.');
    expect(text).toContain(
      'Goal: (1.00, 0.00) m, 1.00 m away, bearing 0 deg (90 deg to the right)',
    );
    expect(text).toContain('Range sensors: front 0.90 m');
    const map = text.split('\n').filter((l) => /^[#.?RG*]+$/.test(l));
    expect(map).toHaveLength(25);
    expect(map.every((l) => l.length === 25)).toBe(true);
    expect(text).toContain('R');
    expect(text).toContain('G');
    // The arena's outside (the grid is 5 m, the arena 4 m) is a border of '#'.
    expect(map[0]).toBe('#'.repeat(25));
  });
});

describe('renderGridImage', () => {
  it('draws occupied cells black and free cells white, north up', () => {
    const grid = new OccupancyGrid();
    grid.seedFromMap({ arena: { width: 5, height: 5 } });
    grid.setLogOdds(0, 99, 4); // the top-left cell
    const image = renderGridImage(grid, { size: 200, showInflation: false });
    expect(image.width).toBe(200);
    expect(image.height).toBe(200);
    expect(Array.from(image.data.subarray(0, 4))).toEqual([20, 20, 20, 255]);
    const bottom = (199 * 200 + 0) * 4;
    expect(Array.from(image.data.subarray(bottom, bottom + 4))).toEqual([250, 250, 250, 255]);
  });

  it('encodes a JPEG data URL that decodes to the same size', () => {
    const grid = new OccupancyGrid();
    const url = gridImageDataUrl(grid, {
      pose: { x: 0, y: 0, yaw: 0 },
      goal: { x: 1, y: 1 },
      path: [
        { x: 0, y: 0 },
        { x: 1, y: 1 },
      ],
      size: 100,
    });
    expect(url.startsWith('data:image/jpeg;base64,')).toBe(true);
    const bytes = Buffer.from(url.slice('data:image/jpeg;base64,'.length), 'base64');
    const decoded = jpeg.decode(bytes, { useTArray: true });
    expect(decoded.width).toBe(100);
    expect(decoded.height).toBe(100);
  });
});
