import { cellCentre, worldToCell } from '@hal/navigation';
import type { OccupancyGrid, Point } from '@hal/navigation';

/** A frontier worth driving to: where it is, how far by the grid, and how much it may show. */
export interface FrontierChoice {
  target: Point;
  /** Route length to it by a 4-connected search, metres. */
  distanceM: number;
  /** Unknown cells within `gainRadiusM` of it that no occupied cell hides from it. */
  gain: number;
}

/** Options of {@link mostPromisingFrontier}. */
export interface FrontierChoiceOptions {
  /** Ignore frontiers nearer than this, metres (the blind ring round the robot). Default 0.5. */
  minDistanceM?: number;
  /** Count unknown cells within this of a frontier, metres, in its line of sight (the camera's reach). Default 2.5. */
  gainRadiusM?: number;
  /** Ignore frontiers within `excludeRadiusM` of these (already tried). */
  exclude?: readonly Point[];
  /** Default 0.4. */
  excludeRadiusM?: number;
  /**
   * A heading to favour, radians (where the robot first faced): a frontier's score is weighted by
   * 1 + `headingWeight` x the cosine of its bearing from `from` off this heading.
   */
  heading?: number;
  /** Default 0.3. */
  headingWeight?: number;
}

/**
 * The reachable frontier (a free cell beside unknown space, reached through cells the robot may
 * stand on) that promises most per metre: the unknown cells round it that no occupied cell hides
 * from it (not those behind a wall it saw), divided by one plus the route's length. A camera sees far, so the nearest frontier is usually a patch it merely did not
 * look at; a wide unknown space behind a door is worth the longer drive. Undefined when none is
 * reachable.
 */
export function mostPromisingFrontier(
  grid: OccupancyGrid,
  from: Point,
  options: FrontierChoiceOptions = {},
): FrontierChoice | undefined {
  const { spec, obstacles } = grid;
  const start = worldToCell(spec, from.x, from.y);
  if (start === undefined) return undefined;
  const { width: w, height: h, resolutionM: res } = spec;
  const minSteps = (options.minDistanceM ?? 0.5) / res;
  const reach = Math.round((options.gainRadiusM ?? 2.5) / res);
  const exclude = options.exclude ?? [];
  const excludeR = options.excludeRadiusM ?? 0.4;
  const heading = options.heading;
  const headingWeight = options.headingWeight ?? 0.3;
  const unknown = (x: number, y: number) =>
    x >= 0 && y >= 0 && x < w && y < h && grid.stateOf(x, y) === 'unknown';
  const dist = new Int32Array(w * h).fill(-1);
  const queue = new Int32Array(w * h);
  let head = 0;
  let tail = 0;
  dist[start.cy * w + start.cx] = 0;
  queue[tail++] = start.cy * w + start.cx;
  let best: FrontierChoice | undefined;
  let bestScore = 0;
  while (head < tail) {
    const u = queue[head++] as number;
    const ux = u % w;
    const uy = (u - ux) / w;
    const d = dist[u] as number;
    if (
      d >= minSteps &&
      grid.stateOf(ux, uy) === 'free' &&
      (unknown(ux - 1, uy) || unknown(ux + 1, uy) || unknown(ux, uy - 1) || unknown(ux, uy + 1))
    ) {
      const target = cellCentre(spec, ux, uy);
      if (!exclude.some((p) => Math.hypot(p.x - target.x, p.y - target.y) < excludeR)) {
        let gain = 0;
        // every third cell each way: a ninth of the work, much the same ranking
        for (let dy = -reach; dy <= reach; dy += 3) {
          for (let dx = -reach; dx <= reach; dx += 3) {
            if (dx * dx + dy * dy > reach * reach || !unknown(ux + dx, uy + dy)) continue;
            if (inSight(grid, ux, uy, dx, dy)) gain += 1;
          }
        }
        const distanceM = d * res;
        const bearing = Math.atan2(target.y - from.y, target.x - from.x);
        const ahead = heading === undefined ? 1 : 1 + headingWeight * Math.cos(bearing - heading);
        const score = (ahead * gain) / (1 + distanceM);
        if (score > bestScore) {
          bestScore = score;
          best = { target, distanceM, gain };
        }
      }
    }
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
  return best;
}

/** Whether no occupied cell lies on the straight line from cell (x, y) to (x + dx, y + dy). */
function inSight(grid: OccupancyGrid, x: number, y: number, dx: number, dy: number): boolean {
  const steps = Math.max(Math.abs(dx), Math.abs(dy));
  for (let k = 1; k < steps; k += 1) {
    const cx = x + Math.round((dx * k) / steps);
    const cy = y + Math.round((dy * k) / steps);
    if (grid.stateOf(cx, cy) === 'occupied') return false;
  }
  return true;
}
