import type { GridSpec } from './geometry.js';

/**
 * Visits the cells a straight segment from world point (x0, y0) to (x1, y1) passes through, in
 * order (an exact grid traversal), clipped to the grid. The visitor gets each cell's column and
 * row and returns false to stop early. The last cell visited is the one holding (x1, y1) when
 * that point lies on the grid.
 */
export function traverseCells(
  spec: GridSpec,
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  visit: (cx: number, cy: number) => boolean | void,
): void {
  const res = spec.resolutionM;
  // Work in cell units.
  const ax = (x0 - spec.originX) / res;
  const ay = (y0 - spec.originY) / res;
  const bx = (x1 - spec.originX) / res;
  const by = (y1 - spec.originY) / res;
  const dx = bx - ax;
  const dy = by - ay;
  // Clip the parameter range t in [0, 1] to the grid rectangle (Liang-Barsky).
  let t0 = 0;
  let t1 = 1;
  const clip = (p: number, q: number): boolean => {
    if (p === 0) return q >= 0;
    const r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      if (r > t0) t0 = r;
    } else {
      if (r < t0) return false;
      if (r < t1) t1 = r;
    }
    return true;
  };
  if (
    !clip(-dx, ax) ||
    !clip(dx, spec.width - ax) ||
    !clip(-dy, ay) ||
    !clip(dy, spec.height - ay)
  ) {
    return;
  }
  const sx = ax + t0 * dx;
  const sy = ay + t0 * dy;
  const ex = ax + t1 * dx;
  const ey = ay + t1 * dy;
  const clamp = (v: number, size: number) => Math.min(size - 1, Math.max(0, Math.floor(v)));
  let cx = clamp(sx, spec.width);
  let cy = clamp(sy, spec.height);
  const endX = clamp(ex, spec.width);
  const endY = clamp(ey, spec.height);
  const stepX = dx > 0 ? 1 : dx < 0 ? -1 : 0;
  const stepY = dy > 0 ? 1 : dy < 0 ? -1 : 0;
  // Parameters along the original segment at which it next crosses a vertical / horizontal edge.
  const tDeltaX = stepX === 0 ? Infinity : 1 / Math.abs(dx);
  const tDeltaY = stepY === 0 ? Infinity : 1 / Math.abs(dy);
  let tMaxX = stepX === 0 ? Infinity : t0 + (stepX > 0 ? cx + 1 - sx : sx - cx) * tDeltaX;
  let tMaxY = stepY === 0 ? Infinity : t0 + (stepY > 0 ? cy + 1 - sy : sy - cy) * tDeltaY;
  // A generous bound on the number of cells, so rounding can never loop forever.
  let budget = Math.abs(endX - cx) + Math.abs(endY - cy) + 2;
  for (;;) {
    if (visit(cx, cy) === false) return;
    if ((cx === endX && cy === endY) || budget <= 0) return;
    budget -= 1;
    if (tMaxX < tMaxY) {
      cx += stepX;
      tMaxX += tDeltaX;
    } else {
      cy += stepY;
      tMaxY += tDeltaY;
    }
    if (cx < 0 || cy < 0 || cx >= spec.width || cy >= spec.height) return;
  }
}
