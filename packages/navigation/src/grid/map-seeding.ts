import type { GridExtent } from './geometry.js';
import { mapSolids } from './known-map.js';
import type { KnownMap, MapSolid } from './known-map.js';
import type { LogOddsGrid } from './log-odds-grid.js';

/** Log-odds of a cell a known map shows free: free, but one range hit makes it occupied. */
const SEEDED_FREE = -0.2;

/** How {@link seedGridFromMap} marks cells. */
export interface SeedOptions {
  /** Mark the open space inside the arena free (default true); false leaves it unknown. */
  freeSpace?: boolean;
  /** Log-odds of open space. Default -0.2. */
  freeLogOdds?: number;
  /** Log-odds of solid cells and cells outside the arena. Default the model's max. */
  occupiedLogOdds?: number;
}

/**
 * Seeds the grid from a known map: cells touching a wall or obstacle become occupied with full
 * confidence, cells outside the arena too, and (unless `freeSpace` is false) every other cell
 * inside the arena free with low confidence (one range hit marks an obstacle the map did not show).
 */
export function seedGridFromMap(grid: LogOddsGrid, map: KnownMap, options: SeedOptions = {}): void {
  const freeValue = options.freeLogOdds ?? SEEDED_FREE;
  const occupiedValue = options.occupiedLogOdds ?? grid.model.max;
  const { width, height, resolutionM: res, originX, originY } = grid.spec;
  const solids = mapSolids(map);
  const arena = map.arena;
  for (let cy = 0; cy < height; cy += 1) {
    for (let cx = 0; cx < width; cx += 1) {
      const minX = originX + cx * res;
      const minY = originY + cy * res;
      const cell = { minX, minY, maxX: minX + res, maxY: minY + res };
      const occupied =
        (arena !== undefined && outsideArena(cell, arena)) ||
        solids.some((solid) => touches(cell, solid));
      if (occupied) grid.setLogOdds(cx, cy, occupiedValue);
      else if (options.freeSpace !== false) grid.setLogOdds(cx, cy, freeValue);
    }
  }
}

/** Whether a cell reaches outside the arena rectangle centred on the origin. */
function outsideArena(cell: GridExtent, arena: { width: number; height: number }): boolean {
  return (
    cell.minX < -arena.width / 2 ||
    cell.maxX > arena.width / 2 ||
    cell.minY < -arena.height / 2 ||
    cell.maxY > arena.height / 2
  );
}

/** Whether a cell overlaps a solid (open intervals: touching an edge does not count). */
function touches(cell: GridExtent, solid: MapSolid): boolean {
  if (solid.kind === 'rect') {
    return (
      cell.minX < solid.maxX &&
      cell.maxX > solid.minX &&
      cell.minY < solid.maxY &&
      cell.maxY > solid.minY
    );
  }
  const nx = Math.min(Math.max(solid.x, cell.minX), cell.maxX);
  const ny = Math.min(Math.max(solid.y, cell.minY), cell.maxY);
  return (nx - solid.x) ** 2 + (ny - solid.y) ** 2 < solid.radius * solid.radius;
}
