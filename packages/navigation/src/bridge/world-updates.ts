import type { CallMotion, HALToolResult } from '@hal/types';
import { distance, forEachCellInDisc, worldToCell } from '../grid/geometry.js';
import type { Point, Pose2D } from '../grid/geometry.js';
import type { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { BridgeContext, RunState } from './bridge-context.js';
import { readPose } from './sensing.js';

/** The point `metres` ahead of the robot along its heading (behind it when negative). */
export function pointAlong(pose: Pose2D, metres: number): Point {
  return { x: pose.x + metres * Math.cos(pose.yaw), y: pose.y + metres * Math.sin(pose.yaw) };
}

/**
 * Marks the cell `reachM` ahead of the robot occupied (two hits' worth), for what it ran into or
 * could not get past: the planner then routes round it.
 */
export function markObstacleAhead(grid: OccupancyGrid, pose: Pose2D, reachM: number): void {
  const ahead = pointAlong(pose, reachM);
  const cell = worldToCell(grid.spec, ahead.x, ahead.y);
  if (cell !== undefined) grid.addEvidence(cell.cx, cell.cy, 2 * grid.model.hit);
}

/**
 * Reads the pose once more after a run-ending action, for the trajectory; after a collision, records
 * what the robot ran into, just ahead of where it stopped.
 */
export async function refreshPose(ctx: BridgeContext, state: RunState): Promise<void> {
  const read = await readPose(ctx);
  if (!('pose' in read)) return;
  state.trajectory.push(read.pose);
  if (state.lastHalResult?.code === 'COLLISION') {
    markObstacleAhead(ctx.grid, read.pose, ctx.grid.robotRadiusM + ctx.grid.spec.resolutionM / 2);
  }
}

/** Whether the robot's footprint, swept from `from` to `to`, touches an unknown cell. */
export function entersUnknown(grid: OccupancyGrid, from: Point, to: Point): boolean {
  const { resolutionM } = grid.spec;
  const reach = grid.robotRadiusM + resolutionM / 2;
  const steps = Math.max(1, Math.ceil(distance(from, to) / (resolutionM / 2)));
  let unknown = false;
  for (let k = 1; k <= steps && !unknown; k += 1) {
    const x = from.x + ((to.x - from.x) * k) / steps;
    const y = from.y + ((to.y - from.y) * k) / steps;
    forEachCellInDisc(grid.spec, x, y, reach, (cx, cy) => {
      unknown = grid.stateOf(cx, cy) === 'unknown';
      return !unknown;
    });
  }
  return unknown;
}

/**
 * A guard between the bridge and the wheels refused or stopped a forward motion (OBSTACLE_AHEAD)
 * because it saw something ahead, `details.distanceM` metres beyond the body's front: records
 * it there (two hits' worth) along the direction of travel (toward a `point`'s target, else the
 * heading), so the planner routes round what the guard saw and the bridge's own sensors missed.
 */
export function markGuardedObstacle(
  ctx: BridgeContext,
  state: RunState,
  motion: CallMotion,
  args: Record<string, number | string>,
  result: HALToolResult,
): void {
  const pose = state.trajectory.at(-1);
  const aheadM = result.details?.['distanceM'];
  if (pose === undefined || typeof aheadM !== 'number' || !(aheadM >= 0)) return;
  let heading = pose.yaw;
  if (motion === 'point') {
    const x = Number(args['x']);
    const y = Number(args['y']);
    if (!Number.isFinite(x) || !Number.isFinite(y) || distance(pose, { x, y }) < 0.01) return;
    heading = Math.atan2(y - pose.y, x - pose.x);
  } else if (motion !== 'forward') {
    return;
  }
  const { grid } = ctx;
  const reach = grid.robotRadiusM + aheadM + grid.spec.resolutionM / 2;
  markObstacleAhead(grid, { x: pose.x, y: pose.y, yaw: heading }, reach);
}
