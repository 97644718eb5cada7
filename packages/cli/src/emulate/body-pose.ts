// Where the emulated robot's body truly is: its wheel steps integrated from the world's start with
// the V1 cube's nominal geometry. The emulated wheels are perfect, so the steps the robot made are
// the motion of the body; its own configuration (set_config, a calibration) changes what the
// robot believes, not where the body goes.
import { OdometryIntegrator, V1_GEOMETRY } from '@hal/kinematics';
import type { RobotGeometry } from '@hal/kinematics';

/** Absolute wheel positions, steps (as the robot counts them from boot). */
export interface WheelPositions {
  left: number;
  right: number;
}

/** A pose in the world: metres and radians. */
export interface WorldPose {
  x: number;
  y: number;
  yaw: number;
}

/**
 * The body's true pose from the wheel positions a robot reports. The first positions seen are
 * where the body stood at `start` (the robot's counters at boot, 0 and 0 by default).
 */
export class BodyPose {
  readonly #odometry: OdometryIntegrator;

  constructor(
    start: WorldPose,
    geometry: RobotGeometry = V1_GEOMETRY,
    at: WheelPositions = { left: 0, right: 0 },
  ) {
    this.#odometry = new OdometryIntegrator(
      geometry,
      { xCm: start.x * 100, yCm: start.y * 100, headingRad: start.yaw },
      at.left,
      at.right,
    );
  }

  /** Moves the body by the steps made since the last positions. */
  update(wheels: WheelPositions): void {
    this.#odometry.update(wheels.left, wheels.right);
  }

  /** The pose now, metres and radians. */
  get pose(): WorldPose {
    const p = this.#odometry.pose;
    return { x: p.xCm / 100, y: p.yCm / 100, yaw: p.headingRad };
  }
}
