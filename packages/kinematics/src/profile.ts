import { HalError } from '@hal/types';

/**
 * The trapezoidal motion profile of one wheel, and the discrete step times the firmware's step
 * planner uses. The formulas and their operation order are the firmware's (see docs/kinematics.md),
 * so the simulation reproduces the robot's steps to the microsecond.
 */

function requirePositive(name: string, value: number): void {
  if (typeof value !== 'number' || !Number.isFinite(value) || value <= 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${name}" must be a finite number greater than 0, got ${String(value)}`,
    );
  }
}

/** Rounds seconds to whole microseconds as the firmware does: floor(t * 1e6 + 0.5). */
export function toMicros(seconds: number): number {
  return Math.floor(seconds * 1e6 + 0.5);
}

/** A move of `steps` whole steps from rest to rest. */
export class TrapezoidalProfile {
  /** Whole steps of the move (>= 0). */
  readonly steps: number;
  /** Cruise speed, steps/s. */
  readonly speed: number;
  /** Acceleration and deceleration, steps/s^2. */
  readonly acceleration: number;
  /** True when the move reaches cruise speed (a trapezoid), false for a triangle. */
  readonly reachesCruise: boolean;
  /** Steps spent accelerating to cruise speed (fractional). */
  readonly accelSteps: number;
  /** Continuous duration, s. */
  readonly durationSeconds: number;

  constructor(steps: number, speed: number, acceleration: number) {
    if (!Number.isInteger(steps) || steps < 0) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"steps" must be a whole number >= 0, got ${String(steps)}`,
      );
    }
    requirePositive('speed', speed);
    requirePositive('acceleration', acceleration);
    this.steps = steps;
    this.speed = speed;
    this.acceleration = acceleration;
    this.accelSteps = (speed * speed) / (2.0 * acceleration);
    this.reachesCruise = steps * acceleration >= speed * speed;
    this.durationSeconds = this.reachesCruise
      ? steps / speed + speed / acceleration
      : 2.0 * Math.sqrt(steps / acceleration);
  }

  /** When step `k` (1..steps) happens, s after the start. */
  stepTime(k: number): number {
    const { steps: n, speed: v, acceleration: a } = this;
    if (this.reachesCruise) {
      if (k <= this.accelSteps) return Math.sqrt((2.0 * k) / a);
      if (k <= n - this.accelSteps) return v / a + (k - this.accelSteps) / v;
      return this.durationSeconds - Math.sqrt((2.0 * (n - k)) / a);
    }
    if (2 * k <= n) return Math.sqrt((2.0 * k) / a);
    return this.durationSeconds - Math.sqrt((2.0 * (n - k)) / a);
  }

  /** When step `k` (1..steps) happens, whole microseconds after the start. */
  stepTimeUs(k: number): number {
    return toMicros(this.stepTime(k));
  }

  /** When the last step happens, whole microseconds (0 for an empty move). */
  get durationUs(): number {
    return this.steps === 0 ? 0 : this.stepTimeUs(this.steps);
  }

  /** Continuous position along the profile at `t` seconds, steps (0..steps). */
  positionAt(t: number): number {
    const { steps: n, speed: v, acceleration: a } = this;
    if (t <= 0) return 0;
    if (t >= this.durationSeconds) return n;
    const rampTime = this.reachesCruise ? v / a : this.durationSeconds / 2;
    if (t <= rampTime) return 0.5 * a * t * t;
    const remaining = this.durationSeconds - t;
    if (t >= this.durationSeconds - rampTime) return n - 0.5 * a * remaining * remaining;
    return this.accelSteps + v * (t - rampTime);
  }

  /** Continuous speed along the profile at `t` seconds, steps/s. */
  velocityAt(t: number): number {
    const { speed: v, acceleration: a } = this;
    if (t <= 0 || t >= this.durationSeconds) return 0;
    const rampTime = this.reachesCruise ? v / a : this.durationSeconds / 2;
    if (t <= rampTime) return a * t;
    if (t >= this.durationSeconds - rampTime) return a * (this.durationSeconds - t);
    return v;
  }

  /** Whole steps done `elapsedUs` microseconds after the start: the largest k with stepTimeUs(k) <= elapsedUs. */
  stepsDoneAt(elapsedUs: number): number {
    if (elapsedUs <= 0 || this.steps === 0) return 0;
    if (elapsedUs >= this.durationUs) return this.steps;
    let k = Math.min(this.steps, Math.floor(this.positionAt(elapsedUs / 1e6)));
    while (k < this.steps && this.stepTimeUs(k + 1) <= elapsedUs) k += 1;
    while (k > 0 && this.stepTimeUs(k) > elapsedUs) k -= 1;
    return k;
  }
}

/** Constant-speed running from rest (the firmware's `drive`): accelerate, then cruise forever. */
export class VelocityProfile {
  readonly speed: number;
  readonly acceleration: number;
  readonly accelSteps: number;

  constructor(speed: number, acceleration: number) {
    requirePositive('speed', speed);
    requirePositive('acceleration', acceleration);
    this.speed = speed;
    this.acceleration = acceleration;
    this.accelSteps = (speed * speed) / (2.0 * acceleration);
  }

  /** When step `k` (>= 1) happens, s after the start. */
  stepTime(k: number): number {
    const { speed: v, acceleration: a } = this;
    if (k <= this.accelSteps) return Math.sqrt((2.0 * k) / a);
    return v / a + (k - this.accelSteps) / v;
  }

  stepTimeUs(k: number): number {
    return toMicros(this.stepTime(k));
  }

  positionAt(t: number): number {
    const { speed: v, acceleration: a } = this;
    if (t <= 0) return 0;
    const rampTime = v / a;
    if (t <= rampTime) return 0.5 * a * t * t;
    return this.accelSteps + v * (t - rampTime);
  }

  velocityAt(t: number): number {
    if (t <= 0) return 0;
    return Math.min(this.speed, this.acceleration * t);
  }

  stepsDoneAt(elapsedUs: number): number {
    if (elapsedUs <= 0) return 0;
    let k = Math.floor(this.positionAt(elapsedUs / 1e6));
    while (this.stepTimeUs(k + 1) <= elapsedUs) k += 1;
    while (k > 0 && this.stepTimeUs(k) > elapsedUs) k -= 1;
    return k;
  }
}

/**
 * Duration of a trapezoidal move in milliseconds, rounded (the seed's function). 1706 steps at
 * 1024 steps/s and 512 steps/s^2 -> 3651 ms; 2172 steps -> 4121 ms.
 */
export function calculateMoveDuration(
  steps: number,
  maxSpeed: number,
  acceleration: number,
): number {
  const n = Math.abs(steps);
  if (n === 0) return 0;
  return Math.round(
    new TrapezoidalProfile(Math.round(n), maxSpeed, acceleration).durationSeconds * 1000,
  );
}
