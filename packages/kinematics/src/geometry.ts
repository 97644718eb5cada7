import { V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';

/** The geometry the step math needs. Any {@link RobotConfig} is one. */
export type RobotGeometry = Pick<
  RobotConfig,
  'stepsPerRevolution' | 'wheelDiameterCm' | 'wheelBaseCm'
>;

/** The motion limits of the step planner. Any {@link RobotConfig} is one. */
export type MotionLimits = Pick<RobotConfig, 'maxSpeedStepsPerS' | 'accelerationStepsPerS2'>;

/** The V1 stepper cube: 4096 steps/rev, 6 cm wheels, 10 cm wheel base, 1024 steps/s, 512 steps/s^2. */
export const V1_GEOMETRY: RobotGeometry & MotionLimits = V1_ROBOT;

/**
 * pi, written out so the firmware's C++ (`kPi`) uses the very same double. Every formula in this
 * package keeps the operation order the firmware uses, so both compute bit-identical results.
 */
export const PI = 3.141592653589793;

/** Wheel circumference, cm. */
export function wheelCircumferenceCm(geometry: RobotGeometry = V1_GEOMETRY): number {
  return PI * geometry.wheelDiameterCm;
}

/** Steps per centimetre of wheel travel (V1: ~217.3). */
export function getStepsPerCm(geometry: RobotGeometry = V1_GEOMETRY): number {
  return geometry.stepsPerRevolution / (PI * geometry.wheelDiameterCm);
}
