import { OdometryIntegrator, StepAccumulator } from '@hal/kinematics';
import type { PlanarPoseCm, RobotGeometry, StepPlan, WheelPair } from '@hal/kinematics';
import type { MoveOutcome } from '../protocol/schemas.js';
import type { RobotClock } from './robot-clock.js';

interface Motion {
  plan: StepPlan;
  startUs: number;
  /** Cap on the motion's length, robot µs (a drive with a duration). */
  endUs: number;
  baseLeft: number;
  baseRight: number;
}

/** What the motion state is given. */
export interface MotionStateOptions {
  clock: RobotClock;
  geometry: RobotGeometry;
  /** The robot's host timeout, ms (read on every step: `set_config` may change it). */
  hostTimeoutMs: () => number;
  /** Called when the host timeout stops a motion. */
  onHostTimeout: () => void;
  /** Called when a motion starts. */
  onMotionStarted: () => void;
}

/**
 * The wheels: absolute step counters, the running motion (a `@hal/kinematics` step plan, so the
 * steps are the firmware's to the microsecond), the per-wheel distance accumulators, odometry,
 * and the host timeout that stops a motion when the host goes quiet.
 */
export class MotionState {
  readonly #options: MotionStateOptions;
  #left = 0;
  #right = 0;
  #odometry = new OdometryIntegrator();
  #accLeft = new StepAccumulator();
  #accRight = new StepAccumulator();
  #motion: Motion | undefined;
  #moveId = 0;
  #outcome: MoveOutcome = 'none';
  #moveLeft = 0;
  #moveRight = 0;
  #lastHostUs = 0;
  #restUs = 0;

  constructor(options: MotionStateOptions) {
    this.#options = options;
    this.setGeometry(options.geometry);
  }

  /** The absolute wheel positions, steps. */
  get position(): WheelPair {
    return { left: this.#left, right: this.#right };
  }

  get running(): boolean {
    return this.#motion !== undefined;
  }

  /** The id of the last motion. */
  get moveId(): number {
    return this.#moveId;
  }

  get outcome(): MoveOutcome {
    return this.#outcome;
  }

  /** Steps the last motion has made on each wheel. */
  get moveSteps(): WheelPair {
    return { left: this.#moveLeft, right: this.#moveRight };
  }

  /** Robot µs when the wheels last came to rest (the end of the last motion; 0: never moved). */
  get restUs(): number {
    return this.#restUs;
  }

  /** The odometry pose, cm and radians. */
  get pose(): PlanarPoseCm {
    return this.#odometry.pose;
  }

  /** The wheel speeds now, steps/s. */
  velocity(): WheelPair {
    const m = this.#motion;
    return m === undefined
      ? { left: 0, right: 0 }
      : m.plan.velocityAt(this.#options.clock.us() - m.startUs);
  }

  /** Robot ms since the host was last heard. */
  msSinceHost(): number {
    return Math.max(0, Math.floor((this.#options.clock.us() - this.#lastHostUs) / 1000));
  }

  /** The host was heard: the host timeout starts over. */
  contact(): void {
    this.#lastHostUs = this.#options.clock.us();
  }

  /** The whole steps to issue for a wheel's travel of `cm`, through its accumulator. */
  addCm(wheel: 'left' | 'right', cm: number): number {
    return (wheel === 'left' ? this.#accLeft : this.#accRight).add(cm);
  }

  /** Forgets the accumulated fractions (a new session). */
  resetAccumulators(): void {
    this.#accLeft.reset();
    this.#accRight.reset();
  }

  /** Uses a new geometry: fresh accumulators, odometry continuing from the pose and counters. */
  setGeometry(geometry: RobotGeometry): void {
    this.#accLeft = new StepAccumulator(geometry);
    this.#accRight = new StepAccumulator(geometry);
    const pose = this.#odometry.pose;
    this.#odometry = new OdometryIntegrator(geometry, pose, this.#left, this.#right);
  }

  /** Brings the wheels up to the present (finishing or timing out the motion). */
  advance(): void {
    const m = this.#motion;
    if (m === undefined) return;
    const now = this.#options.clock.us();
    const hostTimeoutMs = this.#options.hostTimeoutMs();
    const timeoutAt = this.#lastHostUs + hostTimeoutMs * 1000;
    const end = Math.min(m.startUs + m.plan.durationUs, m.startUs + m.endUs);
    const until = Math.min(now, end, timeoutAt);
    this.#stepTo(m, until - m.startUs);
    if (until === timeoutAt && timeoutAt <= now && timeoutAt < end) {
      this.#motion = undefined;
      this.#restUs = timeoutAt;
      this.#outcome = 'host_timeout';
      this.#options.onHostTimeout();
    } else if (until === end && end <= now) {
      this.#motion = undefined;
      this.#restUs = end;
      this.#outcome = 'done';
    }
  }

  /** Starts a motion from rest, replacing any running one; `endUs` caps its length. */
  begin(plan: StepPlan, endUs: number): void {
    this.stop('replaced');
    this.#moveId += 1;
    this.#options.onMotionStarted();
    this.#moveLeft = 0;
    this.#moveRight = 0;
    this.#outcome = 'running';
    if (endUs === 0) {
      this.#outcome = 'done';
      return;
    }
    this.#motion = {
      plan,
      startUs: this.#options.clock.us(),
      endUs,
      baseLeft: this.#left,
      baseRight: this.#right,
    };
  }

  /** Stops the running motion at once with this outcome; returns whether one was running. */
  stop(outcome: MoveOutcome): boolean {
    this.advance();
    if (this.#motion === undefined) return false;
    this.#motion = undefined;
    this.#outcome = outcome;
    this.#restUs = this.#options.clock.us();
    return true;
  }

  /** A power cycle: counters, motion and odometry start over (the host contact time is kept). */
  restart(geometry: RobotGeometry): void {
    this.#left = 0;
    this.#right = 0;
    this.#motion = undefined;
    this.#moveId = 0;
    this.#outcome = 'none';
    this.#odometry.reset();
    this.setGeometry(geometry);
  }

  #stepTo(m: Motion, elapsedUs: number): void {
    const steps = m.plan.stepsAt(Math.max(0, elapsedUs));
    this.#left = m.baseLeft + steps.left;
    this.#right = m.baseRight + steps.right;
    this.#moveLeft = steps.left;
    this.#moveRight = steps.right;
    this.#odometry.update(this.#left, this.#right);
  }
}
