import type { ObstacleMap } from './obstacle-map.js';

/**
 * Whether the straight segment between the centres of cells (x0, y0) and (x1, y1) crosses only
 * cells the robot may stand on. Every cell the segment passes through is checked (an exact
 * traversal in integer arithmetic); where it passes exactly through a cell corner, both cells
 * beside the corner must be free, the same rule that stops A* cutting corners.
 */
export function lineOfSight(
  map: ObstacleMap,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
): boolean {
  if (map.isBlocked(x0, y0) || map.isBlocked(x1, y1)) return false;
  const adx = Math.abs(x1 - x0);
  const ady = Math.abs(y1 - y0);
  const stepX = Math.sign(x1 - x0);
  const stepY = Math.sign(y1 - y0);
  // The segment runs t = 0..1; it next crosses a vertical cell edge at t = nx / (2 adx ady) and a
  // horizontal one at t = ny / (2 adx ady). Comparing nx with ny needs no division.
  let nx = adx === 0 ? Infinity : ady === 0 ? 1 : ady;
  let ny = ady === 0 ? Infinity : adx === 0 ? 1 : adx;
  const incX = ady === 0 ? 2 : 2 * ady;
  const incY = adx === 0 ? 2 : 2 * adx;
  let x = x0;
  let y = y0;
  while (x !== x1 || y !== y1) {
    if (nx === ny) {
      if (map.isBlocked(x + stepX, y) || map.isBlocked(x, y + stepY)) return false;
      x += stepX;
      y += stepY;
      nx += incX;
      ny += incY;
    } else if (nx < ny) {
      x += stepX;
      nx += incX;
    } else {
      y += stepY;
      ny += incY;
    }
    if (map.isBlocked(x, y)) return false;
  }
  return true;
}

/**
 * Shortens a cell path by line of sight: from each kept cell, jumps to the farthest later cell
 * of the path in sight of it. The result starts and ends where the path does, and every segment
 * of it passes the {@link lineOfSight} test.
 */
export function simplifyPath(map: ObstacleMap, cells: readonly number[]): number[] {
  if (cells.length <= 2) return [...cells];
  const w = map.width;
  const kept: number[] = [cells[0] as number];
  let anchor = 0;
  while (anchor < cells.length - 1) {
    const a = cells[anchor] as number;
    const ax = a % w;
    const ay = (a - ax) / w;
    let next = anchor + 1;
    for (let j = anchor + 2; j < cells.length; j += 1) {
      const b = cells[j] as number;
      const bx = b % w;
      if (!lineOfSight(map, ax, ay, bx, (b - bx) / w)) break;
      next = j;
    }
    kept.push(cells[next] as number);
    anchor = next;
  }
  return kept;
}
