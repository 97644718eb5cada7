import type { Pose2D } from '../grid/geometry.js';
import type { OccupancyGrid } from '../grid/occupancy-grid.js';

/** What the bridge hands a {@link WorldObserver} each cycle. */
export interface WorldObservation {
  /** The cycle, 1 for the first. */
  cycle: number;
  /** This cycle's camera frame (a JPEG data URL), or undefined when the camera gave none in time. */
  frame: string | undefined;
  /** The robot's believed pose when the frame was asked for (the pose this cycle read). */
  pose: Pose2D;
  /** The world model: the observer lays what it perceives into it (free space, obstacles). */
  grid: OccupancyGrid;
}

/**
 * What the bridge perceives each cycle beside its range sensors: given the cycle's frame and
 * pose, it updates the grid (and whatever else it keeps, such as a memory of objects) before the
 * provider decides. It is waited for at most the bridge's sensor timeout; one that throws or is
 * slow is logged and the cycle goes on without it (a slow one is not cancelled: it may still
 * write into the grid when it settles). The bridge does not know what it does: perception lives
 * above navigation and plugs in here.
 */
export type WorldObserver = (observation: WorldObservation) => Promise<void> | void;
