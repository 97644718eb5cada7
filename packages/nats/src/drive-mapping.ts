import { HalError, maxLinearSpeedMPerS } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { DifferentialCommand } from './messages.js';

/** Wheel powers for `LocomotionInterface.drive`, -255..255 each. */
export interface WheelPowers {
  left: number;
  right: number;
}

/**
 * Maps a body velocity onto wheel powers: each wheel's ground speed is v -/+ w * base / 2
 * (left/right, REP-103: positive w turns counter-clockwise), and power 255 is the robot's top
 * wheel speed. A command that needs a wheel faster than the top speed is refused with
 * RANGE_EXCEEDED rather than clipped, so the robot never drives a different curve than asked.
 */
export function wheelPowersFor(command: DifferentialCommand, robot: RobotConfig): WheelPowers {
  const v = command.linear_vel_m_per_s;
  const w = command.angular_vel_rad_per_s;
  for (const [name, value] of [
    ['linear_vel_m_per_s', v],
    ['angular_vel_rad_per_s', w],
  ] as const) {
    if (!Number.isFinite(value)) {
      throw new HalError('INVALID_PARAMETER', `"${name}" must be a finite number`, {
        details: { parameter: name },
      });
    }
  }
  const halfBaseM = robot.wheelBaseCm / 200;
  const top = maxLinearSpeedMPerS(robot);
  const leftMPerS = v - w * halfBaseM;
  const rightMPerS = v + w * halfBaseM;
  const fastest = Math.max(Math.abs(leftMPerS), Math.abs(rightMPerS));
  if (fastest > top * (1 + 1e-9)) {
    throw new HalError(
      'RANGE_EXCEEDED',
      `"linear_vel_m_per_s" and "angular_vel_rad_per_s" need a wheel at ${fastest.toFixed(4)} m/s; the top wheel speed is ${top.toFixed(4)} m/s`,
      { details: { parameter: 'linear_vel_m_per_s', requested: fastest, maximum: top } },
    );
  }
  const power = (speed: number) => Math.max(-255, Math.min(255, Math.round((speed / top) * 255)));
  return { left: power(leftMPerS), right: power(rightMPerS) };
}

/** Wheel and body velocities from a pose's body velocity (for `motor.differential.state`). */
export function wheelVelocities(
  linearMPerS: number,
  angularRadPerS: number,
  robot: RobotConfig,
): { left_vel_m_per_s: number; right_vel_m_per_s: number } {
  const halfBaseM = robot.wheelBaseCm / 200;
  return {
    left_vel_m_per_s: linearMPerS - angularRadPerS * halfBaseM,
    right_vel_m_per_s: linearMPerS + angularRadPerS * halfBaseM,
  };
}
