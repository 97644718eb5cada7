import { rotationArcCm } from '@hal/kinematics';
import { HalError, normalizeAngle, robotConfig, stepsPerCm, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import { BodyErrorModel, hasBodyError, parseBodyError } from './body-error.js';
import type { BodyErrorInput } from './body-error.js';
import type { ContactTest, FreeSpaceTest } from './contact.js';
import { MotionExecutor } from './motion-executor.js';
import type { MotionHandle, MotionReport } from './motion-report.js';
import { RobotSafety } from './robot-safety.js';
import type { SafetyTrip } from './robot-safety.js';
import { clampDriveSpeeds, clampSpeed, requireFinite } from './speed-limits.js';
import { WheelAccumulator } from './wheel-accumulator.js';

/*
 * The simulated V1 stepper cube, as its firmware moves it (docs/protocol.md section 5): the same
 * commands (move_steps, move_cm, rotate_deg, drive, stop, estop, reset_estop, set_config), the
 * same per-wheel step accumulators, the same discrete step planner (@hal/kinematics MovePlan and
 * VelocityPlan: master on the trapezoidal profile, slave by Bresenham), the same limits (speed
 * clamp, 40960 steps per command with an e-stop trip), the same host timeout, and odometry by
 * the firmware's formula. The world advances it on its clock and tells it what it touches.
 *
 * This file is the command layer; the motion state and step execution are a MotionExecutor, the
 * e-stop, step limit and host timeout a RobotSafety.
 *
 * In a world, the robot is advanced only at its events (a step that must be checked for contact,
 * the end of a motion, the host timeout: see `nextEventUs`); between them, reading its state or
 * commanding it first catches it up to the world's clock with the steps that need no check.
 */

/** How a world drives a robot's time (see {@link SimRobot.setScheduler}). */
export interface RobotScheduler {
  /** The world's simulated time, µs. */
  nowUs(): number;
  /** The robot's next event may have moved; `everyone`: the room of every robot changed. */
  reschedule(everyone: boolean): void;
}

/** The status LED. */
export interface LedState {
  r: number;
  g: number;
  b: number;
  pattern: 'solid' | 'blink' | 'pulse' | 'off';
}

export interface SimRobotOptions {
  id: string;
  /** Geometry and limits; default the V1 robot. */
  config?: RobotConfig;
  /** Start pose, metres and radians, world frame. */
  start?: { x: number; y: number; yaw: number };
  /** Radius of the robot's footprint for collisions, metres. Default 0.07 (a 10 cm cube). */
  radius?: number;
  /** How the body differs from the nominal one (wheel diameters, slip, odometry). Default none. */
  bodyError?: BodyErrorInput;
}

/** The simulated robot. Commands act at the robot's current simulated time. */
export class SimRobot {
  readonly id: string;
  /** Footprint radius, metres. */
  readonly radius: number;
  /** The body's error (see body-error.ts), or undefined when it is the nominal one. */
  readonly bodyError: BodyErrorInput | undefined;
  #config: RobotConfig;
  #perCm: number;
  #nowUs = 0;
  #led: LedState = { r: 0, g: 0, b: 0, pattern: 'off' };
  readonly #motions: MotionExecutor;
  readonly #safety: RobotSafety;
  readonly #accLeft: WheelAccumulator;
  readonly #accRight: WheelAccumulator;
  #scheduler: RobotScheduler | undefined;

  constructor(options: SimRobotOptions) {
    this.id = options.id;
    this.radius = options.radius ?? 0.07;
    this.#config = options.config ?? V1_ROBOT;
    this.#perCm = stepsPerCm(this.#config);
    const start = options.start ?? { x: 0, y: 0, yaw: 0 };
    const pose = { xCm: start.x * 100, yCm: start.y * 100, headingRad: normalizeAngle(start.yaw) };
    const body = parseBodyError(options.bodyError);
    this.bodyError = hasBodyError(body) ? body : undefined;
    this.#motions = new MotionExecutor(
      pose,
      this.radius,
      () => this.#scheduler?.reschedule(false),
      this.bodyError === undefined ? undefined : new BodyErrorModel(body),
    );
    this.#safety = new RobotSafety({
      nowUs: () => this.#nowUs,
      stopMotion: (outcome) => this.#motions.finish(outcome, this.#nowUs),
    });
    this.#accLeft = new WheelAccumulator(() => this.#config);
    this.#accRight = new WheelAccumulator(() => this.#config);
  }

  /**
   * The world sets how the robot learns what it touches and, optionally, how much room it has
   * (without it every step is checked).
   */
  setContactTest(test: ContactTest, freeSpace?: FreeSpaceTest): void {
    this.#motions.setContactTest(test, freeSpace);
  }

  /** The world sets its clock and is told when the robot's next event may have moved. */
  setScheduler(scheduler: RobotScheduler): void {
    this.#scheduler = scheduler;
  }

  /** Forgets the room last measured (the world changed around the robot). */
  invalidateRoom(): void {
    this.#motions.invalidateRoom();
  }

  /** Brings the robot up to the world's clock with the steps that need no check. */
  #catchUp(): void {
    const scheduler = this.#scheduler;
    if (scheduler === undefined) return;
    const now = scheduler.nowUs();
    if (now > this.#nowUs) {
      this.#motions.catchUp(now);
      this.#nowUs = now;
    }
  }

  /**
   * When the robot next needs the world's attention, µs: a step to check for contact, the end of
   * its motion, or a silent host's timeout; Infinity at rest.
   */
  get nextEventUs(): number {
    const motion = this.#motions.nextEventUs;
    if (motion === Number.POSITIVE_INFINITY) return motion;
    return Math.min(motion, this.#safety.silentDeadlineUs(this.#config.hostTimeoutMs));
  }

  /**
   * The most the centre can move per second, m/s: the top speed on a straight line, or the
   * running motion's, if it started under a higher limit.
   */
  get maxSpeedMps(): number {
    const running = this.#motions.running ? (this.#motions.motion?.speed ?? 0) : 0;
    return Math.max(this.#config.maxSpeedStepsPerS, running) / this.#perCm / 100;
  }

  /** Length of one wheel step, metres. */
  get stepLengthM(): number {
    return 1 / this.#perCm / 100;
  }

  /** Centre, metres, as last integrated (without catching up), and when, µs. */
  get settledX(): number {
    return this.#motions.xCm / 100;
  }
  get settledY(): number {
    return this.#motions.yCm / 100;
  }
  get settledUs(): number {
    return this.#nowUs;
  }

  get config(): RobotConfig {
    return this.#config;
  }
  /** The robot's simulated time, µs. */
  get nowUs(): number {
    this.#catchUp();
    return this.#nowUs;
  }
  /** Pose, metres and radians (REP-103). */
  get x(): number {
    this.#catchUp();
    return this.#motions.xCm / 100;
  }
  get y(): number {
    this.#catchUp();
    return this.#motions.yCm / 100;
  }
  get yaw(): number {
    this.#catchUp();
    return this.#motions.pose.headingRad;
  }
  /**
   * The pose the robot reports, metres and radians: its odometry, which a body error makes drift
   * from the true pose ({@link x}, {@link y}, {@link yaw}); without one, the true pose.
   */
  get reportedPose(): { x: number; y: number; yaw: number } {
    this.#catchUp();
    const p = this.#motions.reportedPose;
    return { x: p.xCm / 100, y: p.yCm / 100, yaw: p.headingRad };
  }
  /** Absolute wheel positions since the start, steps. */
  get leftSteps(): number {
    this.#catchUp();
    return this.#motions.leftSteps;
  }
  get rightSteps(): number {
    this.#catchUp();
    return this.#motions.rightSteps;
  }
  get running(): boolean {
    return this.#motions.running;
  }
  /** The running motion, or the last one. */
  get motion(): MotionReport | undefined {
    this.#catchUp();
    return this.#motions.motion;
  }
  get emergencyStopped(): boolean {
    return this.#safety.emergencyStopped;
  }
  get emergencyStopReason(): string {
    return this.#safety.emergencyStopReason;
  }
  get trips(): number {
    return this.#safety.trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#safety.lastTrip;
  }
  get led(): LedState {
    return { ...this.#led };
  }
  /** Whether the host is (simulated as) silent: no heartbeats between commands. */
  get hostSilent(): boolean {
    return this.#safety.hostSilent;
  }

  /** Current signed wheel speeds, steps/s (0 at rest). */
  wheelSpeeds(atUs = this.nowUs): { left: number; right: number } {
    return this.#motions.wheelSpeeds(atUs);
  }

  /** Linear (m/s) and angular (rad/s) velocity of the robot's centre. */
  velocity(atUs = this.nowUs): { linear: number; angular: number } {
    if (!this.#motions.running) return { linear: 0, angular: 0 };
    const w = this.wheelSpeeds(atUs);
    const l = w.left / this.#perCm;
    const r = w.right / this.#perCm;
    return { linear: (l + r) / 200, angular: (r - l) / this.#config.wheelBaseCm };
  }

  // ---- host link -------------------------------------------------------------------------

  /** A valid request from the host arrived now (every command counts; so do heartbeats). */
  touchHost(): void {
    this.#catchUp();
    this.#safety.touchHost();
  }

  /**
   * Simulates a host that goes silent (true: no heartbeats; a running motion stops after the
   * host timeout) or speaks again (false).
   */
  setHostSilent(silent: boolean): void {
    this.#catchUp();
    this.#safety.setHostSilent(silent);
    this.#scheduler?.reschedule(false);
  }

  // ---- firmware commands -------------------------------------------------------------------

  /** `move_steps`: whole signed steps per wheel. Does not touch the accumulators. */
  moveSteps(left: number, right: number, speed?: number): MotionHandle {
    this.touchHost();
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
    this.#safety.checkStepLimit(left, right, this.#config.maxStepsPerCommand);
    return this.#motions.startMove(
      left,
      right,
      used.speed,
      used.clamped,
      this.#nowUs,
      this.#config,
    );
  }

  /**
   * `move_cm`: a distance per wheel through the accumulators (equal: straight; else an arc).
   * Every argument is checked before anything changes: a refused command leaves the
   * accumulators, the motion and the safety state as they were.
   */
  moveCm(leftCm: number, rightCm: number, speed?: number): MotionHandle {
    requireFinite('left_cm', leftCm);
    requireFinite('right_cm', rightCm);
    this.touchHost();
    this.#safety.refuseWhileLatched();
    const used = clampSpeed(speed, this.#config.maxSpeedStepsPerS);
    const left = this.#accLeft.add(leftCm);
    const right = this.#accRight.add(rightCm);
    try {
      this.#safety.checkStepLimit(left, right, this.#config.maxStepsPerCommand);
    } catch (error) {
      this.#accLeft.undo();
      this.#accRight.undo();
      throw error;
    }
    return this.#motions.startMove(
      left,
      right,
      used.speed,
      used.clamped,
      this.#nowUs,
      this.#config,
    );
  }

  /** `rotate_deg`: turn in place; positive degrees counter-clockwise (left wheel backwards). */
  rotateDeg(degrees: number, speed?: number): MotionHandle {
    const arc = rotationArcCm(degrees, this.#config);
    return this.moveCm(-arc, arc, speed);
  }

  /**
   * `drive`: velocity mode at signed whole steps/s per wheel, from rest; both scaled together
   * (truncated toward zero) when the faster exceeds the top speed. Runs until `durationMs`,
   * a stop, a new motion, an e-stop or the host timeout. Both 0: stops and returns undefined.
   */
  drive(leftSps: number, rightSps: number, durationMs?: number): MotionHandle | undefined {
    requireFinite('left_sps', leftSps);
    requireFinite('right_sps', rightSps);
    if (durationMs !== undefined) requireFinite('duration_ms', durationMs, { positive: true });
    this.touchHost();
    this.#safety.refuseWhileLatched();
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
    this.touchHost();
    return this.#motions.finish('stopped', this.#nowUs);
  }

  /** `estop`: stops at once and latches until {@link resetEmergencyStop}. */
  emergencyStop(reason = 'estop command'): void {
    this.touchHost();
    this.#safety.emergencyStop(reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  resetEmergencyStop(): boolean {
    this.touchHost();
    return this.#safety.reset();
  }

  /** `set_config`: applies to the next motion; resets the distance accumulators. */
  setConfig(overrides: Partial<RobotConfig>): RobotConfig {
    this.touchHost();
    this.#config = robotConfig({ ...this.#config, ...overrides });
    this.#perCm = stepsPerCm(this.#config);
    this.#motions.reconfigure(this.#config);
    // A new top speed or geometry changes how fast this robot can reach the others.
    this.#scheduler?.reschedule(true);
    this.#accLeft.reset();
    this.#accRight.reset();
    return this.#config;
  }

  /** `hello`: a host opens a session; the distance accumulators are reset (nothing else changes). */
  hello(): void {
    this.touchHost();
    this.#accLeft.reset();
    this.#accRight.reset();
  }

  /** `set_led`. */
  setLed(led: LedState): void {
    this.touchHost();
    this.#led = { ...led };
  }

  // ---- time ------------------------------------------------------------------------------

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

  /** When the running motion's next event (its end) is due, µs, or Infinity. */
  get motionEndUs(): number {
    return this.#motions.endUs;
  }
}
