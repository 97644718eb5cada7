import { BUILTIN_MAPS, parseMap } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { emptyGridOf, perceivedGridView } from './perceived-grid.js';

describe('the perceived grid', () => {
  it("covers the map's arena and starts all unknown, whatever the map's obstacles", () => {
    const grid = emptyGridOf(parseMap(BUILTIN_MAPS.obstacles));
    expect([grid.spec.width, grid.spec.height, grid.spec.resolutionM]).toStrictEqual([
      100, 100, 0.05,
    ]);
    expect([grid.spec.originX, grid.spec.originY]).toStrictEqual([-2.5, -2.5]);
    const view = perceivedGridView(grid);
    expect(view.data.length).toBe(100 * 100);
    expect(Array.from(view.data).every((v) => v === -1)).toBe(true);
  });

  it('shows what the camera saw: free cells below 0.5, occupied above', () => {
    const grid = emptyGridOf(parseMap(BUILTIN_MAPS.empty));
    // a ray from the origin along +x, ending on something at 1 m
    grid.integrateRay(0, 0, 0, 1, true);
    const view = perceivedGridView(grid);
    const at = (x: number, y: number) =>
      view.data[
        Math.floor((y - view.origin.y) / view.resolution) * view.width +
          Math.floor((x - view.origin.x) / view.resolution)
      ]!;
    expect(at(0.5, 0.01)).toBeGreaterThanOrEqual(0);
    expect(at(0.5, 0.01)).toBeLessThan(0.5);
    expect(at(1.01, 0.01)).toBeGreaterThan(0.5);
    expect(at(-1, 0.01)).toBe(-1);
  });
});
