import type { OccupancyGrid, Pose2D } from '@hal/navigation';
import type { FreeSpaceColumn } from './free-space.js';
import { toWorld } from './project-object.js';

/** Options of {@link integrateFreeSpace}. */
export interface FreeSpaceFusionOptions {
  /** Use every nth scanned column (the grid's cells are wider than a column far off). Default 2. */
  every?: number;
}

/**
 * Lays one frame's free space into the grid, taken at `pose` (the believed pose at capture):
 * per column, free evidence from the nearest floor the camera sees to the first thing that is
 * not floor, and occupied evidence there; a column free to the range limit adds free evidence
 * only. The floor between the robot and the bottom of the image is not observed and not touched.
 */
export function integrateFreeSpace(
  grid: OccupancyGrid,
  pose: Pose2D,
  freeSpace: readonly FreeSpaceColumn[],
  options: FreeSpaceFusionOptions = {},
): void {
  const every = options.every ?? 2;
  if (!(Number.isInteger(every) && every >= 1)) {
    throw new RangeError(`"every" must be a whole number of 1 or more, got ${every}`);
  }
  if (![pose.x, pose.y, pose.yaw].every(Number.isFinite)) return;
  for (let i = 0; i < freeSpace.length; i += every) {
    const column = freeSpace[i];
    if (column === undefined) continue;
    const from = toWorld(pose, column.from);
    const to = toWorld(pose, column.to);
    const length = Math.hypot(to.x - from.x, to.y - from.y);
    grid.integrateRay(from.x, from.y, Math.atan2(to.y - from.y, to.x - from.x), length, column.hit);
  }
}
