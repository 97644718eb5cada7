import { reachableFrontiers } from '@hal/navigation';
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
  const { width: w, height: h, resolutionM: res } = grid.spec;
  const reach = Math.round((options.gainRadiusM ?? 2.5) / res);
  const heading = options.heading;
  const headingWeight = options.headingWeight ?? 0.3;
  const unknown = (x: number, y: number) =>
    x >= 0 && y >= 0 && x < w && y < h && grid.stateOf(x, y) === 'unknown';
  let best: FrontierChoice | undefined;
  let bestScore = 0;
  for (const { target, distanceM, cx, cy } of reachableFrontiers(grid, from, {
    minDistanceM: options.minDistanceM ?? 0.5,
    excludeRadiusM: options.excludeRadiusM ?? 0.4,
    ...(options.exclude === undefined ? {} : { exclude: options.exclude }),
  })) {
    let gain = 0;
    // every third cell each way: a ninth of the work, much the same ranking
    for (let dy = -reach; dy <= reach; dy += 3) {
      for (let dx = -reach; dx <= reach; dx += 3) {
        if (dx * dx + dy * dy > reach * reach || !unknown(cx + dx, cy + dy)) continue;
        if (inSight(grid, cx, cy, dx, dy)) gain += 1;
      }
    }
    const bearing = Math.atan2(target.y - from.y, target.x - from.x);
    const ahead = heading === undefined ? 1 : 1 + headingWeight * Math.cos(bearing - heading);
    const score = (ahead * gain) / (1 + distanceM);
    if (score > bestScore) {
      bestScore = score;
      best = { target, distanceM, gain };
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
