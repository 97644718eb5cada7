import { cellCentre, worldToCell } from './geometry.js';
import type { Point } from './geometry.js';
import type { OccupancyGrid } from './occupancy-grid.js';

/** A frontier target: a free cell the robot can reach that borders unknown space. */
export interface Frontier {
  /** The frontier cell's centre, metres. */
  target: Point;
  /** Route length to it by the search, metres (4-connected steps). */
  distanceM: number;
}

/** Options of {@link findFrontier}. */
export interface FrontierOptions {
  /** Ignore frontiers nearer than this, metres (the robot is already looking at them). Default 0.2. */
  minDistanceM?: number;
  /** Ignore frontiers within `radiusM` of any of these points (e.g. ones that led nowhere). */
  exclude?: readonly Point[];
  /** Radius for `exclude`, metres. Default 0.25. */
  excludeRadiusM?: number;
}

/** A reachable frontier cell, as {@link reachableFrontiers} finds it. */
export interface FrontierCell extends Frontier {
  /** The cell's column and row. */
  cx: number;
  cy: number;
}

/**
 * The reachable frontiers from `from`, nearest first: a breadth-first search over the cells the
 * robot's centre may enter, yielding each free cell with an unknown neighbour (beyond
 * `minDistanceM`, away from `exclude`). Nothing when `from` is off the grid.
 */
export function* reachableFrontiers(
  grid: OccupancyGrid,
  from: Point,
  options: FrontierOptions = {},
): Generator<FrontierCell> {
  const { spec, obstacles } = grid;
  const start = worldToCell(spec, from.x, from.y);
  if (start === undefined) return;
  const w = spec.width;
  const h = spec.height;
  const minSteps = (options.minDistanceM ?? 0.2) / spec.resolutionM;
  const exclude = options.exclude ?? [];
  const excludeR = options.excludeRadiusM ?? 0.25;
  const dist = new Int32Array(w * h).fill(-1);
  const queue = new Int32Array(w * h);
  let head = 0;
  let tail = 0;
  const s = start.cy * w + start.cx;
  dist[s] = 0;
  queue[tail++] = s;
  const isUnknown = (x: number, y: number) =>
    x >= 0 && y >= 0 && x < w && y < h && grid.stateOf(x, y) === 'unknown';
  while (head < tail) {
    const u = queue[head++] as number;
    const ux = u % w;
    const uy = (u - ux) / w;
    const d = dist[u] as number;
    if (
      d >= minSteps &&
      grid.stateOf(ux, uy) === 'free' &&
      (isUnknown(ux - 1, uy) ||
        isUnknown(ux + 1, uy) ||
        isUnknown(ux, uy - 1) ||
        isUnknown(ux, uy + 1))
    ) {
      const target = cellCentre(spec, ux, uy);
      if (!exclude.some((p) => Math.hypot(p.x - target.x, p.y - target.y) < excludeR)) {
        yield { target, distanceM: d * spec.resolutionM, cx: ux, cy: uy };
      }
    }
    // Expand through cells the robot may stand on (the start cell always, so a robot that is
    // a little too close to a wall can still search).
    const next = [u - 1, u + 1, u - w, u + w];
    const ok = [ux > 0, ux < w - 1, uy > 0, uy < h - 1];
    for (let k = 0; k < 4; k += 1) {
      if (!ok[k]) continue;
      const v = next[k] as number;
      if (dist[v] !== -1) continue;
      const vx = v % w;
      if (obstacles.isBlocked(vx, (v - vx) / w)) continue;
      dist[v] = d + 1;
      queue[tail++] = v;
    }
  }
}

/**
 * The nearest reachable frontier from `from` (the first of {@link reachableFrontiers}): a free
 * cell with an unknown neighbour. Undefined when no frontier is reachable (the reachable space is
 * fully explored) or `from` is off the grid.
 */
export function findFrontier(
  grid: OccupancyGrid,
  from: Point,
  options: FrontierOptions = {},
): Frontier | undefined {
  for (const { target, distanceM } of reachableFrontiers(grid, from, options)) {
    return { target, distanceM };
  }
  return undefined;
}
