import { describe, expect, it } from 'vitest';
import { OccupancyGrid, worldToCell } from '@hal/navigation';
import { mostPromisingFrontier } from './frontier-choice.js';

/** A 4 m grid: known free for x < 0 but for small unknown nooks, a wall at x = 0 (a door optional). */
function room(
  door: boolean,
  nooks = [(x: number, y: number) => x < -1.5 && y < -1.5],
): OccupancyGrid {
  const grid = new OccupancyGrid({ widthM: 4, heightM: 4 });
  const { resolutionM } = grid.spec;
  for (let x = -1.975; x < 0; x += resolutionM) {
    for (let y = -1.975; y < 2; y += resolutionM) {
      const nook = nooks.some((inNook) => inNook(x, y));
      if (!nook) grid.markFree(x, y, 0.01);
    }
  }
  for (let y = -1.975; y < 2; y += resolutionM) {
    const cell = worldToCell(grid.spec, 0.025, y);
    if (cell === undefined) continue;
    if (door && Math.abs(y) < 0.4) grid.markFree(0.025, y, 0.01);
    else grid.addEvidence(cell.cx, cell.cy, 4 * grid.model.hit);
  }
  return grid;
}

describe('mostPromisingFrontier', () => {
  it('prefers the wide unknown through a door to a nearer small nook', () => {
    const choice = mostPromisingFrontier(room(true), { x: -1, y: -1 });
    expect(choice).toBeDefined();
    expect(choice?.target.x).toBeGreaterThan(-0.2);
    expect(Math.abs(choice?.target.y ?? 9)).toBeLessThan(0.45);
  });

  it('does not count what lies behind a wall it has seen', () => {
    // two nooks alike, one against the wall (the unknown beyond it is hidden), one nearer
    const byTheWall = (x: number, y: number) => x > -0.45 && y < -1.5;
    const nearer = (x: number, y: number) => x < -1.5 && y > 1.5;
    const grid = room(false, [byTheWall, nearer]);
    const choice = mostPromisingFrontier(grid, { x: -1.4, y: 0.9 }, { gainRadiusM: 1 });
    expect(choice?.target.x).toBeLessThan(-1.4);
    expect(choice?.target.y).toBeGreaterThan(1.4);
  });

  it('leaves out frontiers already tried, and is undefined when none is left', () => {
    const grid = room(false);
    const first = mostPromisingFrontier(grid, { x: -1, y: -1 });
    expect(first).toBeDefined();
    const exclude = [{ x: -1.6, y: -1.6 }];
    expect(
      mostPromisingFrontier(grid, { x: -1, y: -1 }, { exclude, excludeRadiusM: 0.8 }),
    ).toBeUndefined();
  });
});
