import { HalError, robotConfig, stepsPerCm, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { PlanarPoseCm } from '../odometry.js';
import { rotationArcCm } from '../steps.js';
import { MotionExecutor } from './motion-executor.js';
import type { MotionHandle, MotionReport } from './motion-report.js';
import { RobotSafety } from './robot-safety.js';
import type { SafetyTrip } from './robot-safety.js';
import { checkSettings } from './settings.js';
import {
  clampDriveSpeeds,
  clampSpeed,
  MAX_DRIVE_DURATION_MS,
  requireFinite,
} from './speed-limits.js';
import type { ContactTest, FreeSpaceTest, StepContact } from './step-contact.js';
import { WheelAccumulator } from './wheel-accumulator.js';
import type { BodyScales } from './wheel-scale.js';

/** Options of {@link RobotModel}. */
export interface RobotModelOptions {
  /** Geometry and limits; default the V1 robot. */
  config?: RobotConfig;
  /** Start pose, cm and radians. Default the origin. */
  start?: PlanarPoseCm;
  /** Footprint radius, metres, for contact checks. Default 0.07 (a 10 cm cube). */
  radiusM?: number;
  /** Told whenever a motion starts or ends. */
  onMotionChange?: () => void;
  /**
   * A body that differs from the nominal one: each motion's wheel travel on the ground and in the
   * odometry scaled as it says (the simulator's seeded body error). Default: the nominal body.
   */
  body?: BodyScales;
}

/**
 * The V1 robot's firmware rules, as one model for every TypeScript robot (the simulator's and the
 * in-process mock's); the firmware's C++ core stays the reference, and tests hold the two equal.
 * The commands of protocol section 5 (move_steps, move_cm, rotate_deg, drive, stop, estop,
 * reset_estop, set_config) with the firmware's checks in the firmware's order (the latch, the
 * arguments, the speed, the per-command step limit before anything is committed), the
 * per-wheel step accumulators, the discrete step planner (MovePlan, VelocityPlan), whole-step
 * odometry, the latched e-stop and the host timeout.
 *
 * It has no clock of its own: its owner advances it (`advanceTo`), and tells it when the host
 * was heard (`touchHost`): the commands do not, as in the firmware, where the request layer does.
 * A refused command throws a HalError (the firmware's code, message and details) and changes
 * nothing, except a step-limit refusal, which latches the e-stop as the firmware's does.
 */
export class RobotModel<C extends StepContact = StepContact> {
  #config: RobotConfig;
  #perCm: number;
  #nowUs = 0;
  readonly #motions: MotionExecutor<C>;
  readonly #safety: RobotSafety;
  readonly #accLeft: WheelAccumulator;
  readonly #accRight: WheelAccumulator;

  constructor(options: RobotModelOptions = {}) {
    this.#config = options.config ?? V1_ROBOT;
    this.#perCm = stepsPerCm(this.#config);
    const start = options.start ?? { xCm: 0, yCm: 0, headingRad: 0 };
    this.#motions = new MotionExecutor<C>(
      start,
      options.radiusM ?? 0.07,
      options.onMotionChange,
      options.body,
    );
    this.#safety = new RobotSafety({
      nowUs: () => this.#nowUs,
      stopMotion: (outcome) => this.#motions.finish(outcome, this.#nowUs),
    });
    this.#accLeft = new WheelAccumulator(() => this.#config);
    this.#accRight = new WheelAccumulator(() => this.#config);
  }

  /**
   * How the robot learns what it touches and, optionally, how much room it has (without it every
   * step is checked). Default: it touches nothing.
   */
  setContactTest(test: ContactTest<C>, freeSpace?: FreeSpaceTest): void {
    this.#motions.setContactTest(test, freeSpace);
  }

  /** Forgets the room last measured (the world changed around the robot). */
  invalidateRoom(): void {
    this.#motions.invalidateRoom();
  }

  // ---- state -------------------------------------------------------------------------------

  get config(): RobotConfig {
    return this.#config;
  }
  /** Motor steps per cm of wheel travel, in the current configuration. */
  get stepsPerCm(): number {
    return this.#perCm;
  }
  /** The robot's time, µs: as far as it has been advanced or caught up. */
  get nowUs(): number {
    return this.#nowUs;
  }
  /** Where the body is, cm and radians (REP-103): the odometry's pose when the body is nominal. */
  get pose(): PlanarPoseCm {
    return this.#motions.pose;
  }
  /** The pose the robot reports (its odometry): with a body error it drifts from {@link pose}. */
  get reportedPose(): PlanarPoseCm {
    return this.#motions.reportedPose;
  }
  /** Centre, cm (no allocation). */
  get xCm(): number {
    return this.#motions.xCm;
  }
  get yCm(): number {
    return this.#motions.yCm;
  }
  /** Absolute wheel positions since the start, steps. */
  get leftSteps(): number {
    return this.#motions.leftSteps;
  }
  get rightSteps(): number {
    return this.#motions.rightSteps;
  }
  get running(): boolean {
    return this.#motions.running;
  }
  /** The running motion, or the last one (undefined before the first). */
  get motion(): MotionReport<C> | undefined {
    return this.#motions.motion;
  }
  /** When the running motion's end is due, µs, or Infinity. */
  get motionEndUs(): number {
    return this.#motions.endUs;
  }
  get emergencyStopped(): boolean {
    return this.#safety.emergencyStopped;
  }
  /** The reason stored with the latch ('' when not latched). */
  get emergencyStopReason(): string {
    return this.#safety.emergencyStopReason;
  }
  /** Robot time the latch was last set, µs (0: never). */
  get emergencyStopUs(): number {
    return this.#safety.latchedUs;
  }
  get trips(): number {
    return this.#safety.trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#safety.lastTrip;
  }
  /** Whether the host is silent: heard only at its requests, with no heartbeats between. */
  get hostSilent(): boolean {
    return this.#safety.hostSilent;
  }
  /** Robot time the host was last heard, µs. */
  get lastHostUs(): number {
    return this.#safety.lastHostUs;
  }

  /**
   * When the robot next needs its owner's attention, µs: a step to check for contact, the end of
   * its motion, or a silent host's timeout; Infinity at rest.
   */
  get nextEventUs(): number {
    const motion = this.#motions.nextEventUs;
    if (motion === Number.POSITIVE_INFINITY) return motion;
    return Math.min(motion, this.#safety.silentDeadlineUs(this.#config.hostTimeoutMs));
  }

  /** Current signed wheel speeds, steps/s (0 at rest). */
  wheelSpeeds(atUs = this.#nowUs): { left: number; right: number } {
    return this.#motions.wheelSpeeds(atUs);
  }

  /** Linear (m/s) and angular (rad/s) velocity of the robot's centre. */
  velocity(atUs = this.#nowUs): { linear: number; angular: number } {
    if (!this.#motions.running) return { linear: 0, angular: 0 };
    const w = this.wheelSpeeds(atUs);
    const l = w.left / this.#perCm;
    const r = w.right / this.#perCm;
    return { linear: (l + r) / 200, angular: (r - l) / this.#config.wheelBaseCm };
  }

  // ---- host link ---------------------------------------------------------------------------

  /** A valid request from the host arrived now (every request counts; so do heartbeats). */
  touchHost(): void {
    this.#safety.touchHost();
  }

  /**
   * The host goes silent (true: heard only at its requests, so a running motion stops a host
   * timeout after the last one) or sends its heartbeats again (false: heard throughout).
   */
  setHostSilent(silent: boolean): void {
    this.#safety.setHostSilent(silent);
  }

  // ---- commands ----------------------------------------------------------------------------

  /** Throws EMERGENCY_STOPPED while the e-stop is latched (the first check of every motion). */
  refuseWhileLatched(): void {
    this.#safety.refuseWhileLatched();
  }

  /** `move_steps`: whole signed steps per wheel. Does not touch the accumulators. */
  moveSteps(left: number, right: number, speed?: number): MotionHandle<C> {
    this.#safety.refuseWhileLatched();
    for (const [field, value] of [
      ['left', left],
      ['right', right],
    ] as const) {
      if (!Number.isInteger(value)) {
        throw new HalError('INVALID_PARAMETER', `"${field}" must be an integer`, {
          details: { field, value },
        });
      }
    }
    const used = clampSpeed(speed, this.#config.maxSpeedStepsPerS);
    const limit = this.#config.maxStepsPerCommand;
    this.#safety.checkStepLimit('left', left, limit);
    this.#safety.checkStepLimit('right', right, limit);
    return this.#start(left, right, used);
  }

  /**
   * `move_cm`: a distance per wheel through the accumulators (equal: straight; else an arc).
   * A refused command leaves the accumulators, the motion and the safety state as they were.
   */
  moveCm(leftCm: number, rightCm: number, speed?: number): MotionHandle<C> {
    this.#safety.refuseWhileLatched();
    requireFinite('left_cm', leftCm);
    requireFinite('right_cm', rightCm);
    return this.#moveWheelsCm(leftCm, rightCm, speed, 'left_cm', 'right_cm');
  }

  /** `rotate_deg`: turn in place; positive degrees counter-clockwise (left wheel backwards). */
  rotateDeg(degrees: number, speed?: number): MotionHandle<C> {
    this.#safety.refuseWhileLatched();
    requireFinite('degrees', degrees);
    const arc = rotationArcCm(degrees, this.#config);
    return this.#moveWheelsCm(-arc, arc, speed, 'degrees', 'degrees');
  }

  /**
   * `drive`: velocity mode at signed whole steps/s per wheel, from rest; both scaled together
   * (truncated toward zero) when the faster exceeds the top speed. Runs until `durationMs`
   * (at most 600000), a stop, a new motion, an e-stop or the host timeout. Both 0: stops and
   * returns undefined.
   */
  drive(leftSps: number, rightSps: number, durationMs?: number): MotionHandle<C> | undefined {
    this.#safety.refuseWhileLatched();
    requireFinite('left_sps', leftSps);
    requireFinite('right_sps', rightSps);
    if (durationMs !== undefined) {
      requireFinite('duration_ms', durationMs, { positive: true, max: MAX_DRIVE_DURATION_MS });
    }
    const { left, right, clamped } = clampDriveSpeeds(
      leftSps,
      rightSps,
      this.#config.maxSpeedStepsPerS,
    );
    if (left === 0 && right === 0) {
      this.#motions.finish('stopped', this.#nowUs);
      return undefined;
    }
    return this.#motions.startDrive(left, right, durationMs, clamped, this.#nowUs, this.#config);
  }

  /** `stop`: stops any motion at once. Returns whether one was running. Always accepted. */
  stop(): boolean {
    return this.#motions.finish('stopped', this.#nowUs);
  }

  /** `estop`: stops at once and latches until {@link resetEmergencyStop}; never refused. */
  emergencyStop(reason = 'estop command'): void {
    this.#safety.emergencyStop(reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  resetEmergencyStop(): boolean {
    return this.#safety.reset();
  }

  /**
   * `set_config`: every firmware setting given is checked against the firmware's range (see
   * FIRMWARE_SETTINGS) before anything changes; applies to the rest of the running motion's steps
   * and to the next motion; resets the distance accumulators.
   */
  setConfig(overrides: Partial<RobotConfig>): RobotConfig {
    checkSettings(overrides);
    this.#config = robotConfig({ ...this.#config, ...overrides });
    this.#perCm = stepsPerCm(this.#config);
    this.#motions.reconfigure(this.#config);
    this.resetAccumulators();
    return this.#config;
  }

  /** Forgets the fractions of a step the accumulators carry (`hello`: a new session). */
  resetAccumulators(): void {
    this.#accLeft.reset();
    this.#accRight.reset();
  }

  // ---- time ------------------------------------------------------------------------------

  /**
   * Takes the steps due by `nowUs` that need no contact check and moves the robot's time there
   * (for a reader that wants the pose now; {@link advanceTo} handles the events).
   */
  catchUp(nowUs: number): void {
    if (nowUs <= this.#nowUs) return;
    this.#motions.catchUp(nowUs);
    this.#nowUs = nowUs;
  }

  /**
   * Advances the robot to `nowUs`: executes the steps due by then (stopping at a duration limit,
   * the host timeout or a contact, whichever comes first) and integrates odometry.
   */
  advanceTo(nowUs: number): void {
    const config = this.#config;
    if (nowUs < this.#nowUs) nowUs = this.#nowUs;
    const timeoutUs = this.#safety.hostTimeoutBy(nowUs, config.hostTimeoutMs);
    const outcome = this.#motions.advanceTo(timeoutUs ?? nowUs);
    if (outcome === 'running' && timeoutUs !== undefined) {
      this.#nowUs = Math.min(this.#motions.endUs, timeoutUs);
      this.#safety.hostTimedOut(config.hostTimeoutMs);
    }
    this.#nowUs = nowUs;
  }

  // ---- internals ---------------------------------------------------------------------------

  /** Whole steps for a distance per wheel, checked against the step limit before committing. */
  #moveWheelsCm(
    leftCm: number,
    rightCm: number,
    speed: number | undefined,
    leftField: string,
    rightField: string,
  ): MotionHandle<C> {
    const used = clampSpeed(speed, this.#config.maxSpeedStepsPerS);
    const limit = this.#config.maxStepsPerCommand;
    const left = this.#accLeft.add(leftCm);
    const right = this.#accRight.add(rightCm);
    try {
      this.#safety.checkStepLimit(leftField, left, limit);
      this.#safety.checkStepLimit(rightField, right, limit);
    } catch (error) {
      this.#accLeft.undo();
      this.#accRight.undo();
      throw error;
    }
    return this.#start(left, right, used);
  }

  #start(left: number, right: number, used: { speed: number; clamped: boolean }): MotionHandle<C> {
    return this.#motions.startMove(
      left,
      right,
      used.speed,
      used.clamped,
      this.#nowUs,
      this.#config,
    );
  }
}
