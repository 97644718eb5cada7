import type { Pose2D } from '../grid/geometry.js';
import type { HALToolResult } from '@hal/types';

/**
 * The pose after an action without asking the robot, when the bridge may take it so (the
 * `poseFromResults` option): the pose before it when no motion was called (`result` undefined),
 * or the pose a successful motion's result reports (`data.pose`, the robot's odometry, as both
 * HALs' motion results carry it). Undefined otherwise (a failed motion may have moved part of
 * the way): then the bridge reads the pose.
 */
export function poseFromResult(
  result: HALToolResult | undefined,
  before: Pose2D,
): Pose2D | undefined {
  if (result === undefined) return before;
  if (!result.success) return undefined;
  const pose = result.data?.['pose'];
  if (typeof pose !== 'object' || pose === null) return undefined;
  const { x, y, yaw } = pose as Record<string, unknown>;
  if (typeof x !== 'number' || typeof y !== 'number' || typeof yaw !== 'number') return undefined;
  if (![x, y, yaw].every(Number.isFinite)) return undefined;
  return { x, y, yaw };
}
