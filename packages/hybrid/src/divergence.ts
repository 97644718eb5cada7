import { normalizeAngle } from '@hal/types';
import type { PlanarPose, Pose } from '@hal/types';

/** How far the twin may drift from the physical robot before it counts as diverged. */
export interface DivergenceTolerance {
  /** Largest distance between the two positions, metres. Default 0.005 (5 mm). */
  positionToleranceM: number;
  /** Largest difference between the two headings, radians. Default 0.0175 (1 degree). */
  yawToleranceRad: number;
}

/** The tolerance used when none is given: 5 mm and 1 degree. */
export const DEFAULT_DIVERGENCE_TOLERANCE: Readonly<DivergenceTolerance> = Object.freeze({
  positionToleranceM: 0.005,
  yawToleranceRad: 0.0175,
});

/**
 * How far the twin is from the physical robot. Each pose is taken relative to where its robot
 * stood when the hybrid HAL was initialised (REP-103, in that start frame), so a twin that starts
 * elsewhere in its world is compared by what it did, not where it is.
 */
export interface Divergence {
  /** Distance between the two positions, metres. */
  positionM: number;
  /** Absolute difference between the two headings, radians, 0..pi. */
  yawRad: number;
  /** True when either difference is beyond its tolerance. */
  exceeded: boolean;
}

/** The planar part of a HAL pose. */
export function planar(pose: Pose): PlanarPose {
  return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
}

/** `pose` expressed in the frame of `start` (where the robot stood, facing its start heading). */
export function relativeTo(start: PlanarPose, pose: PlanarPose): PlanarPose {
  const dx = pose.x - start.x;
  const dy = pose.y - start.y;
  const cos = Math.cos(start.yaw);
  const sin = Math.sin(start.yaw);
  return {
    x: cos * dx + sin * dy,
    y: -sin * dx + cos * dy,
    yaw: normalizeAngle(pose.yaw - start.yaw),
  };
}

/** The divergence between two poses given in the same frame. */
export function divergenceBetween(
  physical: PlanarPose,
  twin: PlanarPose,
  tolerance: DivergenceTolerance,
): Divergence {
  const positionM = Math.hypot(physical.x - twin.x, physical.y - twin.y);
  const yawRad = Math.abs(normalizeAngle(physical.yaw - twin.yaw));
  return {
    positionM,
    yawRad,
    exceeded: positionM > tolerance.positionToleranceM || yawRad > tolerance.yawToleranceRad,
  };
}

/** The inverse of {@link relativeTo}: a pose given in the frame of `start`, in the outer frame. */
export function composePose(start: PlanarPose, relative: PlanarPose): PlanarPose {
  const cos = Math.cos(start.yaw);
  const sin = Math.sin(start.yaw);
  return {
    x: start.x + cos * relative.x - sin * relative.y,
    y: start.y + sin * relative.x + cos * relative.y,
    yaw: normalizeAngle(start.yaw + relative.yaw),
  };
}
