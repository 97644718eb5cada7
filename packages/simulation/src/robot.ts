import {
  integrateOdometry,
  MovePlan,
  normalizeAngle,
  rotationArcCm,
  StepAccumulator,
  VelocityPlan,
} from '@hal/kinematics';
import type { PlanarPose, StepPlan } from '@hal/kinematics';
import { HalError, robotConfig, stepsPerCm, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { Point, Solid } from './shapes.js';

/*
 * The simulated V1 stepper cube, as its firmware moves it (docs/protocol.md section 5): the same
 * commands (move_steps, move_cm, rotate_deg, drive, stop, estop, reset_estop, set_config), the
 * same per-wheel step accumulators, the same discrete step planner (@hal/kinematics MovePlan and
 * VelocityPlan: master on the trapezoidal profile, slave by Bresenham), the same limits (speed
 * clamp, 40960 steps per command with an e-stop trip), the same host timeout, and odometry by
 * the firmware's formula. The world advances it on its clock and tells it what it touches.
 */

/** How a motion ended (the firmware's `move_outcome`, plus `collision`, which only a world has). */
export type MoveOutcome =
  'running' | 'done' | 'stopped' | 'estop' | 'host_timeout' | 'replaced' | 'collision';

/** Where the robot touched something. */
export interface Contact {
  /** The contact point, metres, world frame. */
  point: Point;
  /** What was touched. */
  role: Solid['role'];
  /** Which one of its kind (map wall/obstacle index, robot index). */
  index: number;
  /** The robot's id, when another robot was touched. */
  robotId?: string;
}

/** One motion, from its start to its end. */
export interface MotionReport {
  /** Increases by one per motion command. */
  moveId: number;
  /** `move` for move_steps/move_cm/rotate_deg, `drive` for velocity mode. */
  kind: 'move' | 'drive';
  /** Signed steps the motion plans per wheel (moves only). */
  plannedLeft: number;
  plannedRight: number;
  /** Signed wheel speeds, steps/s (drives only). */
  leftSps: number;
  rightSps: number;
  /** The master wheel's cruise speed, steps/s, after clamping. */
  speed: number;
  speedClamped: boolean;
  /** Planned duration, µs (a drive: its duration limit, or Infinity). */
  durationUs: number;
  /** Steps executed so far by this motion. */
  doneLeft: number;
  doneRight: number;
  /** Simulated time the motion started and (once over) ended, µs. */
  startedUs: number;
  endedUs: number | undefined;
  outcome: MoveOutcome;
  /** Set when the outcome is `collision`. */
  contact?: Contact;
}

/** A safety trip, as the firmware records it. */
export interface SafetyTrip {
  reason: 'estop_command' | 'step_limit' | 'host_timeout';
  detail: string;
  /** Simulated time, µs. */
  atUs: number;
}

/** The status LED. */
export interface LedState {
  r: number;
  g: number;
  b: number;
  pattern: 'solid' | 'blink' | 'pulse' | 'off';
}

/** Tells the robot whether a disc at (x, y) of radius r, metres, touches anything. */
export type ContactTest = (x: number, y: number, radius: number) => Contact | undefined;

interface RunningMotion {
  plan: StepPlan;
  report: MotionReport;
  /** Stop at this elapsed time, µs (a move's last step, a drive's duration, or Infinity). */
  limitUs: number;
  settle: (report: MotionReport) => void;
}

/** A started motion: its report so far and a promise of its end. */
export interface MotionHandle {
  report: MotionReport;
  finished: Promise<MotionReport>;
}

export interface SimRobotOptions {
  id: string;
  /** Geometry and limits; default the V1 robot. */
  config?: RobotConfig;
  /** Start pose, metres and radians, world frame. */
  start?: { x: number; y: number; yaw: number };
  /** Radius of the robot's footprint for collisions, metres. Default 0.07 (a 10 cm cube). */
  radius?: number;
}

/** Wheel speed limits the firmware applies to a requested cruise speed. */
function clampSpeed(
  requested: number | undefined,
  max: number,
): { speed: number; clamped: boolean } {
  if (requested === undefined) return { speed: max, clamped: false };
  if (!Number.isFinite(requested) || requested <= 0) {
    throw new HalError('RANGE_EXCEEDED', `"speed" must be 1..${max} steps/s, got ${requested}`, {
      details: { field: 'speed', min: 1, max, value: requested },
    });
  }
  if (requested > max) return { speed: max, clamped: true };
  if (requested < 1) return { speed: 1, clamped: true };
  return { speed: requested, clamped: false };
}

/**
 * A wheel's step accumulator that can take back its last addition, for a command the step limit
 * refuses (the firmware peeks before it commits; a refused command leaves the carry unchanged).
 */
class WheelAccumulator {
  #acc: StepAccumulator;
  #history: number[] = [];
  readonly #config: () => RobotConfig;

  constructor(config: () => RobotConfig) {
    this.#config = config;
    this.#acc = new StepAccumulator(config());
  }

  add(cm: number): number {
    this.#history.push(cm);
    return this.#acc.add(cm);
  }

  /** Forgets the last {@link add} (rare: only a refused command needs it). */
  undo(): void {
    this.#history.pop();
    this.#acc = new StepAccumulator(this.#config());
    for (const cm of this.#history) this.#acc.add(cm);
  }

  reset(): void {
    this.#acc = new StepAccumulator(this.#config());
    this.#history = [];
  }
}

/** The simulated robot. Commands act at the robot's current simulated time. */
export class SimRobot {
  readonly id: string;
  /** Footprint radius, metres. */
  readonly radius: number;
  #config: RobotConfig;
  #pose: PlanarPose;
  #left = 0;
  #right = 0;
  #nowUs = 0;
  #motion: RunningMotion | undefined;
  #last: MotionReport | undefined;
  #nextMoveId = 1;
  #estop = false;
  #estopReason = '';
  #trips = 0;
  #lastTrip: SafetyTrip | undefined;
  #hostSilent = false;
  #lastHostUs = 0;
  #led: LedState = { r: 0, g: 0, b: 0, pattern: 'off' };
  readonly #accLeft: WheelAccumulator;
  readonly #accRight: WheelAccumulator;
  #contactTest: ContactTest = () => undefined;
  #perCm: number;

  constructor(options: SimRobotOptions) {
    this.id = options.id;
    this.radius = options.radius ?? 0.07;
    this.#config = options.config ?? V1_ROBOT;
    this.#perCm = stepsPerCm(this.#config);
    const start = options.start ?? { x: 0, y: 0, yaw: 0 };
    this.#pose = { xCm: start.x * 100, yCm: start.y * 100, headingRad: normalizeAngle(start.yaw) };
    this.#accLeft = new WheelAccumulator(() => this.#config);
    this.#accRight = new WheelAccumulator(() => this.#config);
  }

  /** The world sets how the robot learns what it touches. */
  setContactTest(test: ContactTest): void {
    this.#contactTest = test;
  }

  get config(): RobotConfig {
    return this.#config;
  }
  /** The robot's simulated time, µs. */
  get nowUs(): number {
    return this.#nowUs;
  }
  /** Pose, metres and radians (REP-103). */
  get x(): number {
    return this.#pose.xCm / 100;
  }
  get y(): number {
    return this.#pose.yCm / 100;
  }
  get yaw(): number {
    return this.#pose.headingRad;
  }
  /** Absolute wheel positions since the start, steps. */
  get leftSteps(): number {
    return this.#left;
  }
  get rightSteps(): number {
    return this.#right;
  }
  get running(): boolean {
    return this.#motion !== undefined;
  }
  /** The running motion, or the last one. */
  get motion(): MotionReport | undefined {
    return this.#motion?.report ?? this.#last;
  }
  get emergencyStopped(): boolean {
    return this.#estop;
  }
  get emergencyStopReason(): string {
    return this.#estopReason;
  }
  get trips(): number {
    return this.#trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#lastTrip;
  }
  get led(): LedState {
    return { ...this.#led };
  }
  /** Whether the host is (simulated as) silent: no heartbeats between commands. */
  get hostSilent(): boolean {
    return this.#hostSilent;
  }

  /** Current signed wheel speeds, steps/s (0 at rest). */
  wheelSpeeds(atUs = this.#nowUs): { left: number; right: number } {
    const m = this.#motion;
    if (m === undefined) return { left: 0, right: 0 };
    return m.plan.velocityAt(Math.min(atUs - m.report.startedUs, m.limitUs));
  }

  /** Linear (m/s) and angular (rad/s) velocity of the robot's centre. */
  velocity(atUs = this.#nowUs): { linear: number; angular: number } {
    if (this.#motion === undefined) return { linear: 0, angular: 0 };
    const w = this.wheelSpeeds(atUs);
    const l = w.left / this.#perCm;
    const r = w.right / this.#perCm;
    return { linear: (l + r) / 200, angular: (r - l) / this.#config.wheelBaseCm };
  }

  // ---- host link -------------------------------------------------------------------------

  /** A valid request from the host arrived now (every command counts; so do heartbeats). */
  touchHost(): void {
    this.#lastHostUs = this.#nowUs;
  }

  /**
   * Simulates a host that goes silent (true: no heartbeats; a running motion stops after the
   * host timeout) or speaks again (false).
   */
  setHostSilent(silent: boolean): void {
    if (silent && !this.#hostSilent) this.#lastHostUs = this.#nowUs;
    this.#hostSilent = silent;
  }

  // ---- firmware commands -------------------------------------------------------------------

  /** `move_steps`: whole signed steps per wheel. Does not touch the accumulators. */
  moveSteps(left: number, right: number, speed?: number): MotionHandle {
    this.touchHost();
    this.#refuseWhileStopped();
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
    this.#checkStepLimit(left, right);
    return this.#startMove(left, right, used.speed, used.clamped);
  }

  /** `move_cm`: a distance per wheel through the accumulators (equal: straight; else an arc). */
  moveCm(leftCm: number, rightCm: number, speed?: number): MotionHandle {
    this.touchHost();
    this.#refuseWhileStopped();
    const used = clampSpeed(speed, this.#config.maxSpeedStepsPerS);
    const left = this.#accLeft.add(leftCm);
    const right = this.#accRight.add(rightCm);
    try {
      this.#checkStepLimit(left, right);
    } catch (error) {
      this.#accLeft.undo();
      this.#accRight.undo();
      throw error;
    }
    return this.#startMove(left, right, used.speed, used.clamped);
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
    this.touchHost();
    this.#refuseWhileStopped();
    let l = Math.trunc(leftSps);
    let r = Math.trunc(rightSps);
    const fastest = Math.max(Math.abs(l), Math.abs(r));
    const max = this.#config.maxSpeedStepsPerS;
    let clamped = false;
    if (fastest > max) {
      l = Math.trunc((l * max) / fastest);
      r = Math.trunc((r * max) / fastest);
      clamped = true;
    }
    if (l === 0 && r === 0) {
      this.#finish('stopped');
      return undefined;
    }
    const plan = new VelocityPlan(l, r, this.#config.accelerationStepsPerS2);
    const limitUs = durationMs === undefined ? Number.POSITIVE_INFINITY : durationMs * 1000;
    return this.#start(plan, limitUs, {
      kind: 'drive',
      plannedLeft: 0,
      plannedRight: 0,
      leftSps: l,
      rightSps: r,
      speed: Math.max(Math.abs(l), Math.abs(r)),
      speedClamped: clamped,
      durationUs: limitUs,
    });
  }

  /** `stop`: stops any motion at once. Returns whether one was running. Always accepted. */
  stop(): boolean {
    this.touchHost();
    return this.#finish('stopped');
  }

  /** `estop`: stops at once and latches until {@link resetEmergencyStop}. */
  emergencyStop(reason = 'estop command'): void {
    this.touchHost();
    this.#trip('estop_command', reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  resetEmergencyStop(): boolean {
    this.touchHost();
    const was = this.#estop;
    this.#estop = false;
    this.#estopReason = '';
    return was;
  }

  /** `set_config`: applies to the next motion; resets the distance accumulators. */
  setConfig(overrides: Partial<RobotConfig>): RobotConfig {
    this.touchHost();
    this.#config = robotConfig({ ...this.#config, ...overrides });
    this.#perCm = stepsPerCm(this.#config);
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
    const m = this.#motion;
    if (m === undefined) {
      this.#nowUs = nowUs;
      if (!this.#hostSilent) this.#lastHostUs = nowUs;
      return;
    }
    let until = nowUs;
    let timedOut = false;
    if (this.#hostSilent) {
      const deadline = this.#lastHostUs + this.#config.hostTimeoutMs * 1000;
      if (deadline <= nowUs) {
        until = deadline;
        timedOut = true;
      }
    } else {
      this.#lastHostUs = nowUs;
    }
    const started = m.report.startedUs;
    const elapsed = Math.min(until - started, m.limitUs);
    // A drive makes only the steps due strictly before its duration (the firmware queues no step
    // at or after the limit); a move's limit is the time of its last step, which it makes.
    const steps = m.plan.stepsAt(
      m.report.kind === 'drive' && elapsed >= m.limitUs ? m.limitUs - 1 : elapsed,
    );
    const dl = steps.left - m.report.doneLeft;
    const dr = steps.right - m.report.doneRight;
    if (dl !== 0 || dr !== 0) {
      const next = integrateOdometry(this.#pose, dl, dr, this.#config);
      const contact = this.#touches(next);
      if (contact !== undefined) {
        this.#nowUs = until;
        m.report.contact = contact;
        this.#finish('collision');
        this.#nowUs = nowUs;
        return;
      }
      this.#pose = next;
      this.#left += dl;
      this.#right += dr;
      m.report.doneLeft = steps.left;
      m.report.doneRight = steps.right;
    }
    this.#nowUs = Math.min(started + m.limitUs, until);
    if (elapsed >= m.limitUs) {
      this.#finish('done');
    } else if (timedOut) {
      this.#trip('host_timeout', `no request from the host for ${this.#config.hostTimeoutMs} ms`);
    }
    this.#nowUs = nowUs;
  }

  /** When the running motion's next event (its end) is due, µs, or Infinity. */
  get motionEndUs(): number {
    const m = this.#motion;
    return m === undefined ? Number.POSITIVE_INFINITY : m.report.startedUs + m.limitUs;
  }

  // ---- internals -------------------------------------------------------------------------

  #touches(next: PlanarPose): Contact | undefined {
    const x = next.xCm / 100;
    const y = next.yCm / 100;
    const contact = this.#contactTest(x, y, this.radius);
    if (contact === undefined) return undefined;
    // Moving away from (or along) something already touched is allowed: only a motion that
    // brings the centre closer to the contact point is a collision.
    const before = Math.hypot(this.x - contact.point.x, this.y - contact.point.y);
    const after = Math.hypot(x - contact.point.x, y - contact.point.y);
    return after < before - 1e-12 ? contact : undefined;
  }

  #refuseWhileStopped(): void {
    if (this.#estop) {
      throw new HalError(
        'EMERGENCY_STOPPED',
        `the emergency stop is latched (${this.#estopReason})`,
        {
          details: { reason: this.#estopReason },
        },
      );
    }
  }

  #checkStepLimit(left: number, right: number): void {
    const limit = this.#config.maxStepsPerCommand;
    const worst = Math.abs(left) >= Math.abs(right) ? left : right;
    if (Math.abs(worst) > limit) {
      const field = worst === left ? 'left' : 'right';
      this.#trip('step_limit', `"${field}" ${worst} steps is over the ${limit} step limit`);
      throw new HalError(
        'RANGE_EXCEEDED',
        `"${field}" must be -${limit}..${limit} steps, got ${worst}; the emergency stop has tripped`,
        { details: { field, min: -limit, max: limit, value: worst, estop: true } },
      );
    }
  }

  #trip(reason: SafetyTrip['reason'], detail: string): void {
    this.#trips += 1;
    this.#lastTrip = { reason, detail, atUs: this.#nowUs };
    if (reason === 'host_timeout') {
      this.#finish('host_timeout');
      return;
    }
    this.#finish('estop');
    this.#estop = true;
    this.#estopReason = reason === 'step_limit' ? 'step_limit' : detail;
  }

  #startMove(left: number, right: number, speed: number, clamped: boolean): MotionHandle {
    const plan = new MovePlan(left, right, speed, this.#config.accelerationStepsPerS2);
    return this.#start(plan, plan.durationUs, {
      kind: 'move',
      plannedLeft: left,
      plannedRight: right,
      leftSps: 0,
      rightSps: 0,
      speed,
      speedClamped: clamped,
      durationUs: plan.durationUs,
    });
  }

  #start(
    plan: StepPlan,
    limitUs: number,
    fields: Pick<
      MotionReport,
      | 'kind'
      | 'plannedLeft'
      | 'plannedRight'
      | 'leftSps'
      | 'rightSps'
      | 'speed'
      | 'speedClamped'
      | 'durationUs'
    >,
  ): MotionHandle {
    this.#finish('replaced');
    const report: MotionReport = {
      moveId: this.#nextMoveId,
      ...fields,
      doneLeft: 0,
      doneRight: 0,
      startedUs: this.#nowUs,
      endedUs: undefined,
      outcome: 'running',
    };
    this.#nextMoveId += 1;
    let settle: (r: MotionReport) => void = () => undefined;
    const finished = new Promise<MotionReport>((resolve) => {
      settle = resolve;
    });
    this.#motion = { plan, report, limitUs, settle };
    if (limitUs <= 0) this.#finish('done');
    return { report, finished };
  }

  #finish(outcome: MoveOutcome): boolean {
    const m = this.#motion;
    if (m === undefined) return false;
    this.#motion = undefined;
    m.report.outcome = outcome;
    m.report.endedUs = this.#nowUs;
    this.#last = m.report;
    m.settle(m.report);
    return true;
  }
}
