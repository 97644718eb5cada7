import type { FreeSpaceColumn } from './free-space.js';

/** How far the way straight ahead is clear, from one frame's free space. */
export interface Clearance {
  /**
   * Free distance ahead of the robot's front (its centre plus `bodyRadiusM`), metres: 0 when
   * something is already within the camera's blind zone edge; the range limit when nothing is
   * seen.
   */
  aheadM: number;
  /** Whether something was seen in the corridor (false: free to the range limit). */
  blocked: boolean;
  /** The columns the corridor crossed (none: the camera does not see the corridor). */
  columns: number;
  /** Where the nearest thing in the corridor is, robot frame, metres. */
  at?: { x: number; y: number };
}

/**
 * The clearance in the corridor the robot sweeps driving straight ahead: the free-space
 * boundaries whose lateral offset is within `halfWidthM` (the body's half width plus a margin),
 * nearest first, measured from the body's front.
 */
export function clearanceAhead(
  freeSpace: readonly FreeSpaceColumn[],
  bodyRadiusM: number,
  halfWidthM: number,
): Clearance {
  let nearest = Number.POSITIVE_INFINITY;
  let at: { x: number; y: number } | undefined;
  let range = 0;
  let columns = 0;
  for (const column of freeSpace) {
    const { to } = column;
    if (Math.abs(to.y) > halfWidthM && column.hit) continue;
    if (!column.hit) {
      // Free to the range limit: counts only where the corridor runs through the column's view.
      if (Math.abs(to.y) > halfWidthM && Math.abs(column.from.y) > halfWidthM) continue;
      columns += 1;
      range = Math.max(range, to.x);
      continue;
    }
    columns += 1;
    if (to.x < nearest) {
      nearest = to.x;
      at = { ...to };
    }
  }
  if (at === undefined) {
    return { aheadM: Math.max(0, range - bodyRadiusM), blocked: false, columns };
  }
  return { aheadM: Math.max(0, nearest - bodyRadiusM), blocked: true, columns, at };
}
