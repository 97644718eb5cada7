import { normalizeAngle } from '@hal/types';
import { getStepsPerCm, V1_GEOMETRY } from './geometry.js';
import type { RobotGeometry } from './geometry.js';

/**
 * A planar pose in centimetres, as the firmware's odometry keeps it: REP-103 frame, x forward,
 * y left (cm), heading counter-clockwise (rad). The HAL's own pose in metres is `PlanarPose` in
 * `@hal/types`.
 */
export interface PlanarPoseCm {
  xCm: number;
  yCm: number;
  /** Radians, (-pi, pi]. */
  headingRad: number;
}

/**
 * Advances a pose by wheel step deltas, integrating the exact arc the wheels drove (the firmware's
 * formula: `ds = (dl + dr) / 2`, `dth = (dr - dl) / B`, straight when `|dth| < 1e-12`).
 */
export function integrateOdometry(
  pose: PlanarPoseCm,
  leftSteps: number,
  rightSteps: number,
  geometry: RobotGeometry = V1_GEOMETRY,
): PlanarPoseCm {
  const perCm = getStepsPerCm(geometry);
  const dl = leftSteps / perCm;
  const dr = rightSteps / perCm;
  const ds = (dl + dr) / 2;
  const dth = (dr - dl) / geometry.wheelBaseCm;
  const th = pose.headingRad;
  if (Math.abs(dth) < 1e-12) {
    return { xCm: pose.xCm + ds * Math.cos(th), yCm: pose.yCm + ds * Math.sin(th), headingRad: th };
  }
  const r = ds / dth;
  return {
    xCm: pose.xCm + r * (Math.sin(th + dth) - Math.sin(th)),
    yCm: pose.yCm - r * (Math.cos(th + dth) - Math.cos(th)),
    headingRad: normalizeAngle(th + dth),
  };
}

/** Dead reckoning from absolute step counters (as `get_status` reports them). */
export class OdometryIntegrator {
  #pose: PlanarPoseCm;
  #left: number;
  #right: number;
  readonly #geometry: RobotGeometry;

  constructor(
    geometry: RobotGeometry = V1_GEOMETRY,
    start: PlanarPoseCm = { xCm: 0, yCm: 0, headingRad: 0 },
    leftSteps = 0,
    rightSteps = 0,
  ) {
    this.#geometry = geometry;
    this.#pose = { ...start };
    this.#left = leftSteps;
    this.#right = rightSteps;
  }

  /** Integrates the steps made since the last update, given the absolute counters now. */
  update(leftSteps: number, rightSteps: number): PlanarPoseCm {
    const dl = leftSteps - this.#left;
    const dr = rightSteps - this.#right;
    if (dl !== 0 || dr !== 0) this.#pose = integrateOdometry(this.#pose, dl, dr, this.#geometry);
    this.#left = leftSteps;
    this.#right = rightSteps;
    return this.pose;
  }

  get pose(): PlanarPoseCm {
    return { ...this.#pose };
  }

  /** Restarts from a pose and counters. */
  reset(
    start: PlanarPoseCm = { xCm: 0, yCm: 0, headingRad: 0 },
    leftSteps = 0,
    rightSteps = 0,
  ): void {
    this.#pose = { ...start };
    this.#left = leftSteps;
    this.#right = rightSteps;
  }
}
