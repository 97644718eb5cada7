import { RobotModel } from '@hal/kinematics';
import { normalizeAngle, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { Contact, ContactTest, FreeSpaceTest } from './contact.js';
import type { MotionHandle, MotionReport, SafetyTrip } from './motion-report.js';
import { BodyErrorModel, hasBodyError, parseBodyError } from './body-error.js';
import type { BodyErrorInput } from './body-error.js';

/*
 * The simulated V1 stepper cube, as its firmware moves it (docs/protocol.md section 5): the
 * firmware's rules are @hal/kinematics' RobotModel (the commands, the step accumulators, the step
 * planner, whole-step odometry, the speed clamp, the 40960-step limit with its e-stop trip, the
 * host timeout, the set_config ranges), the one model the in-process mock robot of
 * @hal/physical uses too. This file binds it to a world: the world advances it on its clock and
 * tells it what it touches; every command counts as the host being heard.
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
  #led: LedState = { r: 0, g: 0, b: 0, pattern: 'off' };
  readonly #model: RobotModel<Contact>;
  #scheduler: RobotScheduler | undefined;

  constructor(options: SimRobotOptions) {
    this.id = options.id;
    this.radius = options.radius ?? 0.07;
    const start = options.start ?? { x: 0, y: 0, yaw: 0 };
    const body = parseBodyError(options.bodyError);
    this.bodyError = hasBodyError(body) ? body : undefined;
    this.#model = new RobotModel<Contact>({
      config: options.config ?? V1_ROBOT,
      start: { xCm: start.x * 100, yCm: start.y * 100, headingRad: normalizeAngle(start.yaw) },
      radiusM: this.radius,
      onMotionChange: () => this.#scheduler?.reschedule(false),
      ...(this.bodyError === undefined ? {} : { body: new BodyErrorModel(body) }),
    });
  }

  /**
   * The world sets how the robot learns what it touches and, optionally, how much room it has
   * (without it every step is checked).
   */
  setContactTest(test: ContactTest, freeSpace?: FreeSpaceTest): void {
    this.#model.setContactTest(test, freeSpace);
  }

  /** The world sets its clock and is told when the robot's next event may have moved. */
  setScheduler(scheduler: RobotScheduler): void {
    this.#scheduler = scheduler;
  }

  /** Forgets the room last measured (the world changed around the robot). */
  invalidateRoom(): void {
    this.#model.invalidateRoom();
  }

  /** Brings the robot up to the world's clock with the steps that need no check. */
  #catchUp(): RobotModel<Contact> {
    const scheduler = this.#scheduler;
    if (scheduler !== undefined) this.#model.catchUp(scheduler.nowUs());
    return this.#model;
  }

  /**
   * When the robot next needs the world's attention, µs: a step to check for contact, the end of
   * its motion, or a silent host's timeout; Infinity at rest.
   */
  get nextEventUs(): number {
    return this.#model.nextEventUs;
  }

  /**
   * The most the centre can move per second, m/s: the top speed on a straight line, or the
   * running motion's, if it started under a higher limit.
   */
  get maxSpeedMps(): number {
    const model = this.#model;
    const running = model.running ? (model.motion?.speed ?? 0) : 0;
    return Math.max(model.config.maxSpeedStepsPerS, running) / model.stepsPerCm / 100;
  }

  /** Length of one wheel step, metres. */
  get stepLengthM(): number {
    return 1 / this.#model.stepsPerCm / 100;
  }

  /** Centre, metres, as last integrated (without catching up), and when, µs. */
  get settledX(): number {
    return this.#model.xCm / 100;
  }
  get settledY(): number {
    return this.#model.yCm / 100;
  }
  get settledUs(): number {
    return this.#model.nowUs;
  }

  get config(): RobotConfig {
    return this.#model.config;
  }
  /** The robot's simulated time, µs. */
  get nowUs(): number {
    return this.#catchUp().nowUs;
  }
  /** Pose, metres and radians (REP-103). */
  get x(): number {
    return this.#catchUp().xCm / 100;
  }
  get y(): number {
    return this.#catchUp().yCm / 100;
  }
  get yaw(): number {
    return this.#catchUp().pose.headingRad;
  }
  /**
   * The pose the robot reports, metres and radians: its odometry, which a body error makes drift
   * from the true pose ({@link x}, {@link y}, {@link yaw}); without one, the true pose.
   */
  get reportedPose(): { x: number; y: number; yaw: number } {
    const p = this.#catchUp().reportedPose;
    return { x: p.xCm / 100, y: p.yCm / 100, yaw: p.headingRad };
  }
  /** Absolute wheel positions since the start, steps. */
  get leftSteps(): number {
    return this.#catchUp().leftSteps;
  }
  get rightSteps(): number {
    return this.#catchUp().rightSteps;
  }
  get running(): boolean {
    return this.#model.running;
  }
  /** The running motion, or the last one. */
  get motion(): MotionReport | undefined {
    return this.#catchUp().motion;
  }
  get emergencyStopped(): boolean {
    return this.#model.emergencyStopped;
  }
  get emergencyStopReason(): string {
    return this.#model.emergencyStopReason;
  }
  /** The robot's clock when the last emergency stop latched, µs. */
  get emergencyStopUs(): number {
    return this.#model.emergencyStopUs;
  }
  get trips(): number {
    return this.#model.trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#model.lastTrip;
  }
  get led(): LedState {
    return { ...this.#led };
  }
  /** Whether the host is (simulated as) silent: no heartbeats between commands. */
  get hostSilent(): boolean {
    return this.#model.hostSilent;
  }

  /** Current signed wheel speeds, steps/s (0 at rest). */
  wheelSpeeds(atUs = this.nowUs): { left: number; right: number } {
    return this.#model.wheelSpeeds(atUs);
  }

  /** Linear (m/s) and angular (rad/s) velocity of the robot's centre. */
  velocity(atUs = this.nowUs): { linear: number; angular: number } {
    return this.#model.velocity(atUs);
  }

  // ---- host link -------------------------------------------------------------------------

  /** A valid request from the host arrived now (every command counts; so do heartbeats). */
  touchHost(): void {
    this.#catchUp().touchHost();
  }

  /**
   * Simulates a host that goes silent (true: no heartbeats; a running motion stops after the
   * host timeout) or speaks again (false).
   */
  setHostSilent(silent: boolean): void {
    this.#catchUp().setHostSilent(silent);
    this.#scheduler?.reschedule(false);
  }

  // ---- firmware commands (each is a request: the host is heard first) --------------------

  /** `move_steps`: whole signed steps per wheel. Does not touch the accumulators. */
  moveSteps(left: number, right: number, speed?: number): MotionHandle {
    this.touchHost();
    return this.#model.moveSteps(left, right, speed);
  }

  /**
   * `move_cm`: a distance per wheel through the accumulators (equal: straight; else an arc).
   * Every argument is checked before anything changes: a refused command leaves the
   * accumulators, the motion and the safety state as they were.
   */
  moveCm(leftCm: number, rightCm: number, speed?: number): MotionHandle {
    this.touchHost();
    return this.#model.moveCm(leftCm, rightCm, speed);
  }

  /** `rotate_deg`: turn in place; positive degrees counter-clockwise (left wheel backwards). */
  rotateDeg(degrees: number, speed?: number): MotionHandle {
    this.touchHost();
    return this.#model.rotateDeg(degrees, speed);
  }

  /**
   * `drive`: velocity mode at signed whole steps/s per wheel, from rest; both scaled together
   * (truncated toward zero) when the faster exceeds the top speed. Runs until `durationMs`,
   * a stop, a new motion, an e-stop or the host timeout. Both 0: stops and returns undefined.
   */
  drive(leftSps: number, rightSps: number, durationMs?: number): MotionHandle | undefined {
    this.touchHost();
    return this.#model.drive(leftSps, rightSps, durationMs);
  }

  /** `stop`: stops any motion at once. Returns whether one was running. Always accepted. */
  stop(): boolean {
    this.touchHost();
    return this.#model.stop();
  }

  /** `estop`: stops at once and latches until {@link resetEmergencyStop}. */
  emergencyStop(reason = 'estop command'): void {
    this.touchHost();
    this.#model.emergencyStop(reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  resetEmergencyStop(): boolean {
    this.touchHost();
    return this.#model.resetEmergencyStop();
  }

  /**
   * `set_config`: the firmware's settings are checked against its ranges (RANGE_EXCEEDED,
   * nothing changed); applies to the next motion; resets the distance accumulators.
   */
  setConfig(overrides: Partial<RobotConfig>): RobotConfig {
    this.touchHost();
    const config = this.#model.setConfig(overrides);
    // A new top speed or geometry changes how fast this robot can reach the others.
    this.#scheduler?.reschedule(true);
    return config;
  }

  /** `hello`: a host opens a session; the distance accumulators are reset (nothing else changes). */
  hello(): void {
    this.touchHost();
    this.#model.resetAccumulators();
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
    this.#model.advanceTo(nowUs);
  }

  /** When the running motion's next event (its end) is due, µs, or Infinity. */
  get motionEndUs(): number {
    return this.#model.motionEndUs;
  }
}
