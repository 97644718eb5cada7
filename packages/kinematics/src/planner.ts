import { HalError } from '@hal/types';
import { TrapezoidalProfile, VelocityProfile } from './profile.js';
import type { WheelPair } from './steps.js';

/**
 * The firmware's step planner for both wheels. The master wheel (the one with more steps, or the
 * faster one in velocity mode; the left one on a tie) follows the profile; the slave steps at the
 * same instants by integer Bresenham, `floor(k * M / N)` after the master's k-th step, so both
 * finish together and arcs stay arcs.
 */
export interface StepPlan {
  /** Signed steps each wheel has made `elapsedUs` microseconds after the start. */
  stepsAt(elapsedUs: number): WheelPair;
  /** Signed speed of each wheel at `elapsedUs`, steps/s (continuous profile). */
  velocityAt(elapsedUs: number): WheelPair;
  /** When the last step happens, µs; Infinity for an endless velocity plan. */
  readonly durationUs: number;
  /** Whether the left wheel is the master. */
  readonly leftIsMaster: boolean;
  /**
   * The Bresenham terms: after the master's k-th step the slave has made
   * `floor(k * slaveTerm / masterTerm)` steps (steps of a move, speeds of a velocity plan).
   */
  readonly masterTerm: number;
  readonly slaveTerm: number;
  /** Direction of each wheel: 1, -1, or 0 for a wheel that does not turn. */
  readonly leftSign: number;
  readonly rightSign: number;
  /** Whole steps the master wheel has made `elapsedUs` microseconds after the start. */
  masterStepsAt(elapsedUs: number): number;
  /** When the master wheel's k-th step (k >= 1) happens, whole µs after the start. */
  masterStepTimeUs(k: number): number;
}

function slaveSteps(k: number, slave: number, master: number): number {
  return master === 0 ? 0 : Math.floor((k * slave) / master);
}

function signed(steps: number, sign: number): number {
  return sign < 0 && steps !== 0 ? -steps : steps;
}

/** A move of `left` and `right` whole signed steps, the master at `speed` steps/s. */
export class MovePlan implements StepPlan {
  readonly left: number;
  readonly right: number;
  readonly profile: TrapezoidalProfile;
  readonly leftIsMaster: boolean;
  readonly #master: number;
  readonly #slave: number;

  constructor(left: number, right: number, speed: number, acceleration: number) {
    if (!Number.isInteger(left) || !Number.isInteger(right)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `wheel steps must be whole numbers, got left ${left}, right ${right}`,
      );
    }
    this.left = left;
    this.right = right;
    this.leftIsMaster = Math.abs(left) >= Math.abs(right);
    this.#master = Math.abs(this.leftIsMaster ? left : right);
    this.#slave = Math.abs(this.leftIsMaster ? right : left);
    this.profile = new TrapezoidalProfile(this.#master, speed, acceleration);
  }

  get durationUs(): number {
    return this.profile.durationUs;
  }
  get masterTerm(): number {
    return this.#master;
  }
  get slaveTerm(): number {
    return this.#slave;
  }
  get leftSign(): number {
    return Math.sign(this.left);
  }
  get rightSign(): number {
    return Math.sign(this.right);
  }

  masterStepsAt(elapsedUs: number): number {
    return this.profile.stepsDoneAt(elapsedUs);
  }

  masterStepTimeUs(k: number): number {
    return this.profile.stepTimeUs(k);
  }

  stepsAt(elapsedUs: number): WheelPair {
    const k = this.profile.stepsDoneAt(elapsedUs);
    const s = slaveSteps(k, this.#slave, this.#master);
    return this.leftIsMaster
      ? { left: signed(k, this.left), right: signed(s, this.right) }
      : { left: signed(s, this.left), right: signed(k, this.right) };
  }

  velocityAt(elapsedUs: number): WheelPair {
    const v = this.profile.velocityAt(elapsedUs / 1e6);
    const ratio = this.#master === 0 ? 0 : this.#slave / this.#master;
    const master = v;
    const slave = v * ratio;
    return this.leftIsMaster
      ? { left: Math.sign(this.left) * master, right: Math.sign(this.right) * slave }
      : { left: Math.sign(this.left) * slave, right: Math.sign(this.right) * master };
  }
}

/** Endless running at signed wheel speeds (steps/s, whole numbers), from rest. */
export class VelocityPlan implements StepPlan {
  readonly leftSpeed: number;
  readonly rightSpeed: number;
  readonly leftIsMaster: boolean;
  readonly durationUs = Number.POSITIVE_INFINITY;
  readonly #profile: VelocityProfile | undefined;
  readonly #master: number;
  readonly #slave: number;

  constructor(leftSpeed: number, rightSpeed: number, acceleration: number) {
    if (!Number.isInteger(leftSpeed) || !Number.isInteger(rightSpeed)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `wheel speeds must be whole steps/s, got ${leftSpeed}, ${rightSpeed}`,
      );
    }
    this.leftSpeed = leftSpeed;
    this.rightSpeed = rightSpeed;
    this.leftIsMaster = Math.abs(leftSpeed) >= Math.abs(rightSpeed);
    this.#master = Math.abs(this.leftIsMaster ? leftSpeed : rightSpeed);
    this.#slave = Math.abs(this.leftIsMaster ? rightSpeed : leftSpeed);
    this.#profile =
      this.#master === 0 ? undefined : new VelocityProfile(this.#master, acceleration);
  }

  get masterTerm(): number {
    return this.#master;
  }
  get slaveTerm(): number {
    return this.#slave;
  }
  get leftSign(): number {
    return Math.sign(this.leftSpeed);
  }
  get rightSign(): number {
    return Math.sign(this.rightSpeed);
  }

  masterStepsAt(elapsedUs: number): number {
    return this.#profile?.stepsDoneAt(elapsedUs) ?? 0;
  }

  masterStepTimeUs(k: number): number {
    return this.#profile === undefined ? Number.POSITIVE_INFINITY : this.#profile.stepTimeUs(k);
  }

  stepsAt(elapsedUs: number): WheelPair {
    const k = this.#profile?.stepsDoneAt(elapsedUs) ?? 0;
    const s = slaveSteps(k, this.#slave, this.#master);
    return this.leftIsMaster
      ? { left: signed(k, this.leftSpeed), right: signed(s, this.rightSpeed) }
      : { left: signed(s, this.leftSpeed), right: signed(k, this.rightSpeed) };
  }

  velocityAt(elapsedUs: number): WheelPair {
    const v = this.#profile?.velocityAt(elapsedUs / 1e6) ?? 0;
    const ratio = this.#master === 0 ? 0 : this.#slave / this.#master;
    const master = v;
    const slave = v * ratio;
    return this.leftIsMaster
      ? { left: Math.sign(this.leftSpeed) * master, right: Math.sign(this.rightSpeed) * slave }
      : { left: Math.sign(this.leftSpeed) * slave, right: Math.sign(this.rightSpeed) * master };
  }
}
