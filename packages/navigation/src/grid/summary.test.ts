import { describe, expect, it } from 'vitest';
import { boxMap } from './known-map.fixture.js';
import { OccupancyGrid } from './occupancy-grid.js';
import { describeWorld } from './summary.js';

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
