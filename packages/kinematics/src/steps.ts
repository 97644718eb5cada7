import { HalError } from '@hal/types';
import { getStepsPerCm, PI, V1_GEOMETRY } from './geometry.js';
import type { MotionLimits, RobotGeometry } from './geometry.js';

/** A signed step count or speed for each wheel. */
export interface WheelPair {
  left: number;
  right: number;
}

function requireFinite(name: string, value: number): void {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${name}" must be a finite number, got ${String(value)}`,
    );
  }
}

/**
 * The rounding rule, shared with the firmware: exact step counts are truncated toward zero, after a
 * 1e-9 guard so a value that is mathematically whole but computed a hair below is not lost.
 * (90 degrees is 1706.67 steps per wheel and becomes 1706, the specification's figure.)
 */
export function truncateSteps(exactSteps: number): number {
  return exactSteps >= 0 ? Math.floor(exactSteps + 1e-9) : -Math.floor(-exactSteps + 1e-9);
}

/** Exact (fractional) steps for a wheel travel in cm; the firmware computes `(cm * S) / (kPi * D)`. */
export function exactStepsForDistance(
  distanceCm: number,
  geometry: RobotGeometry = V1_GEOMETRY,
): number {
  return (distanceCm * geometry.stepsPerRevolution) / (PI * geometry.wheelDiameterCm);
}

/** Whole steps for a wheel travel in cm (positive forward), by the rounding rule. 10 cm -> 2172. */
export function distanceToSteps(distanceCm: number, geometry: RobotGeometry = V1_GEOMETRY): number {
  requireFinite('distanceCm', distanceCm);
  return truncateSteps(exactStepsForDistance(distanceCm, geometry));
}

/** Wheel travel in cm for a step count. */
export function stepsToDistance(steps: number, geometry: RobotGeometry = V1_GEOMETRY): number {
  requireFinite('steps', steps);
  return steps / getStepsPerCm(geometry);
}

/** Arc each wheel travels in an in-place turn, cm: `((pi * B) * degrees) / 360`. */
export function rotationArcCm(degrees: number, geometry: RobotGeometry = V1_GEOMETRY): number {
  return (PI * geometry.wheelBaseCm * degrees) / 360;
}

/**
 * Wheel steps for an in-place turn. Positive degrees turn counter-clockwise (REP-103 yaw grows):
 * the left wheel goes back, the right wheel forward. 90 -> { left: -1706, right: 1706 }.
 */
export function rotationToSteps(degrees: number, geometry: RobotGeometry = V1_GEOMETRY): WheelPair {
  requireFinite('degrees', degrees);
  const steps = truncateSteps(exactStepsForDistance(rotationArcCm(degrees, geometry), geometry));
  return { left: steps === 0 ? 0 : -steps, right: steps };
}

/** A linear speed in cm/s as wheel steps/s, clamped to +/- the top speed, sign kept. */
export function velocityToStepsPerSecond(
  cmPerSecond: number,
  geometry: RobotGeometry & MotionLimits = V1_GEOMETRY,
): number {
  requireFinite('cmPerSecond', cmPerSecond);
  const stepsPerSecond = cmPerSecond * getStepsPerCm(geometry);
  return Math.sign(stepsPerSecond) * Math.min(Math.abs(stepsPerSecond), geometry.maxSpeedStepsPerS);
}

/**
 * Wheel speeds (steps/s) to drive an arc of `radiusCm` (positive: centre on the left, a
 * counter-clockwise arc) at `speedCmPerS` along the robot's centre. If the outer wheel would exceed
 * the top speed both are scaled down together, so the arc keeps its radius.
 */
export function calculateArcSpeeds(
  radiusCm: number,
  speedCmPerS: number,
  geometry: RobotGeometry & MotionLimits = V1_GEOMETRY,
): WheelPair {
  requireFinite('radiusCm', radiusCm);
  requireFinite('speedCmPerS', speedCmPerS);
  if (radiusCm === 0) {
    throw new HalError(
      'RANGE_EXCEEDED',
      '"radiusCm" must not be 0; an in-place turn is a rotation',
    );
  }
  const halfBase = geometry.wheelBaseCm / 2;
  const perCm = getStepsPerCm(geometry);
  let left = ((speedCmPerS * (radiusCm - halfBase)) / radiusCm) * perCm;
  let right = ((speedCmPerS * (radiusCm + halfBase)) / radiusCm) * perCm;
  const fastest = Math.max(Math.abs(left), Math.abs(right));
  if (fastest > geometry.maxSpeedStepsPerS) {
    const scale = geometry.maxSpeedStepsPerS / fastest;
    left *= scale;
    right *= scale;
  }
  return { left, right };
}

/**
 * Turns distances into whole steps without drift: it carries what each conversion truncated into
 * the next, so 100 moves of 10 cm make 217299 steps, within one step of 1000 cm, not 100 x 2172.
 * The firmware keeps one per wheel for `move_cm` and `rotate_deg` and resets them on `set_config`
 * and on a new session.
 */
export class StepAccumulator {
  #exact = 0;
  #issued = 0;
  readonly #geometry: RobotGeometry;

  constructor(geometry: RobotGeometry = V1_GEOMETRY) {
    this.#geometry = geometry;
  }

  /** Adds a travel in cm and returns the whole steps to issue for it. */
  add(distanceCm: number): number {
    requireFinite('distanceCm', distanceCm);
    this.#exact += exactStepsForDistance(distanceCm, this.#geometry);
    const target = truncateSteps(this.#exact);
    const delta = target - this.#issued;
    this.#issued = target;
    return delta;
  }

  /** Steps issued so far. */
  get issued(): number {
    return this.#issued;
  }

  /** Forgets the carried fraction (on a configuration change or a new session). */
  reset(): void {
    this.#exact = 0;
    this.#issued = 0;
  }
}
