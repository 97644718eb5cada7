import type { RobotConfig } from '@hal/types';
import type { PlanarPoseCm } from '../odometry.js';
import { MovePlan, VelocityPlan } from '../planner.js';
import type { StepPlan } from '../planner.js';
import { blockingContact } from './step-contact.js';
import type { ContactTest, FreeSpaceTest, StepContact } from './step-contact.js';
import type { BodyScales } from './wheel-scale.js';
import type { MotionHandle, MotionReport, MoveOutcome } from './motion-report.js';
import { ReportedOdometry } from './reported-odometry.js';
import { StepOdometry } from './step-odometry.js';

interface RunningMotion<C extends StepContact> {
  plan: StepPlan;
  report: MotionReport<C>;
  /** Stop at this elapsed time, µs (a move's last step, a drive's duration, or Infinity). */
  limitUs: number;
  /** Master steps the motion makes before its limit (Infinity for an endless drive). */
  lastStep: number;
  settle: (report: MotionReport<C>) => void;
}

type MotionFields = Pick<
  MotionReport,
  'kind' | 'plannedLeft' | 'plannedRight' | 'leftSps' | 'rightSps' | 'speed' | 'speedClamped'
>;

/** Margin kept from anything the robot might touch when it takes steps unchecked, metres. */
const CLEARANCE_MARGIN_M = 1e-9;

/**
 * The robot's motion state: at most one running motion (a {@link MovePlan} or a
 * {@link VelocityPlan}), the last one, the pose and the absolute wheel positions.
 *
 * It moves from step to step, not from tick to tick: the plan says in closed form how many whole
 * steps the master wheel has made by any time, and {@link StepOdometry} integrates them one by
 * one. Contacts are checked only where one is possible: after a checked step it asks the world how
 * much room it has (the distance to the nearest solid, and until when no other robot can reach
 * it), and the steps that stay within that room are taken unchecked; the first step beyond it is
 * checked, and not taken if it would bring the footprint into contact, as before.
 */
export class MotionExecutor<C extends StepContact = StepContact> {
  /** Footprint radius, metres. */
  readonly #radius: number;
  readonly #onChange: () => void;
  #contactTest: ContactTest<C> = () => undefined;
  #freeSpace: FreeSpaceTest | undefined;
  readonly #odometry: StepOdometry;
  #motion: RunningMotion<C> | undefined;
  #last: MotionReport<C> | undefined;
  #nextMoveId = 1;
  /** The first master step of the running motion that must be checked for contact. */
  #checkStep = 1;
  readonly #scratch = { xCm: 0, yCm: 0, headingRad: 0 };
  /** With a body error: its draws, the pose the robot reports, and the geometry it counts with. */
  readonly #body: BodyScales | undefined;
  readonly #reported: ReportedOdometry | undefined;
  #countedWith: RobotConfig | undefined;

  /**
   * `onChange` is told whenever a motion starts or ends; `body`, when given, makes the true
   * motion differ from the reported one (the simulator's body error).
   */
  constructor(
    start: PlanarPoseCm,
    radius: number,
    onChange: () => void = () => undefined,
    body?: BodyScales,
  ) {
    this.#odometry = new StepOdometry(start);
    this.#radius = radius;
    this.#onChange = onChange;
    this.#body = body;
    this.#reported = body === undefined ? undefined : new ReportedOdometry(start);
  }

  /** The pose the robot reports (its odometry); without a body error, the true pose. */
  get reportedPose(): PlanarPoseCm {
    const reported = this.#reported;
    if (reported === undefined) return this.#odometry.pose;
    this.#syncReported();
    return reported.pose;
  }

  #syncReported(): void {
    const config = this.#countedWith;
    if (config !== undefined)
      this.#reported?.sync(this.#odometry.left, this.#odometry.right, config);
  }

  /**
   * How the robot learns what it touches, and (optionally) how much room it has; without
   * `freeSpace` every step is checked.
   */
  setContactTest(test: ContactTest<C>, freeSpace?: FreeSpaceTest): void {
    this.#contactTest = test;
    this.#freeSpace = freeSpace;
    this.invalidateRoom();
  }

  /** Forgets the room last measured: the next step is checked (the world changed). */
  invalidateRoom(): void {
    this.#checkStep = this.#odometry.masterSteps + 1;
  }

  get pose(): PlanarPoseCm {
    return this.#odometry.pose;
  }
  /** Centre, cm (no allocation). */
  get xCm(): number {
    return this.#odometry.xCm;
  }
  get yCm(): number {
    return this.#odometry.yCm;
  }
  /** Absolute wheel positions since the start, steps. */
  get leftSteps(): number {
    return this.#odometry.left;
  }
  get rightSteps(): number {
    return this.#odometry.right;
  }
  get running(): boolean {
    return this.#motion !== undefined;
  }
  /** The running motion, or the last one. */
  get motion(): MotionReport<C> | undefined {
    return this.#motion?.report ?? this.#last;
  }
  /** When the running motion's end is due, µs, or Infinity. */
  get endUs(): number {
    const m = this.#motion;
    return m === undefined ? Number.POSITIVE_INFINITY : m.report.startedUs + m.limitUs;
  }

  /**
   * When something next happens to the running motion, µs: its first step that must be checked
   * for contact, or its end; Infinity at rest. Until then it only takes steps that touch nothing.
   */
  get nextEventUs(): number {
    const m = this.#motion;
    if (m === undefined) return Number.POSITIVE_INFINITY;
    const end = m.report.startedUs + m.limitUs;
    if (this.#checkStep > m.lastStep) return end;
    return Math.min(end, m.report.startedUs + m.plan.masterStepTimeUs(this.#checkStep));
  }

  /** Current signed wheel speeds, steps/s (0 at rest). */
  wheelSpeeds(atUs: number): { left: number; right: number } {
    const m = this.#motion;
    if (m === undefined) return { left: 0, right: 0 };
    return m.plan.velocityAt(Math.min(atUs - m.report.startedUs, m.limitUs));
  }

  /** Starts a move of whole signed steps per wheel at `speed` (replacing a running motion). */
  startMove(
    left: number,
    right: number,
    speed: number,
    clamped: boolean,
    nowUs: number,
    config: RobotConfig,
  ): MotionHandle<C> {
    const plan = new MovePlan(left, right, speed, config.accelerationStepsPerS2);
    return this.#start(plan, plan.durationUs, nowUs, config, {
      kind: 'move',
      plannedLeft: left,
      plannedRight: right,
      leftSps: 0,
      rightSps: 0,
      speed,
      speedClamped: clamped,
    });
  }

  /** Starts a drive at signed steps/s per wheel for `durationMs` (undefined: until stopped). */
  startDrive(
    left: number,
    right: number,
    durationMs: number | undefined,
    clamped: boolean,
    nowUs: number,
    config: RobotConfig,
  ): MotionHandle<C> {
    const plan = new VelocityPlan(left, right, config.accelerationStepsPerS2);
    const limitUs = durationMs === undefined ? Number.POSITIVE_INFINITY : durationMs * 1000;
    return this.#start(plan, limitUs, nowUs, config, {
      kind: 'drive',
      plannedLeft: 0,
      plannedRight: 0,
      leftSps: left,
      rightSps: right,
      speed: Math.max(Math.abs(left), Math.abs(right)),
      speedClamped: clamped,
    });
  }

  /** The geometry changed (`set_config`): the running motion's remaining steps use it. */
  reconfigure(config: RobotConfig): void {
    const m = this.#motion;
    this.#syncReported();
    if (this.#countedWith !== undefined) this.#countedWith = config;
    if (m !== undefined) this.#odometry.reconfigure(m.plan, config);
  }

  /** Ends the running motion with `outcome` at `nowUs`. Returns whether one was running. */
  finish(outcome: MoveOutcome, nowUs: number): boolean {
    const m = this.#motion;
    if (m === undefined) return false;
    this.#motion = undefined;
    m.report.outcome = outcome;
    m.report.endedUs = nowUs;
    this.#last = m.report;
    m.settle(m.report);
    this.#onChange();
    return true;
  }

  /**
   * Executes the steps the running motion has made by `untilUs` and integrates odometry over
   * them. Ends the motion `done` at its limit, or `collision` at the instant of a step that would
   * bring the footprint into contact (that step not taken). Returns the motion's outcome
   * (`running` if it goes on), or undefined when no motion is running.
   */
  advanceTo(untilUs: number): MoveOutcome | undefined {
    const m = this.#motion;
    if (m === undefined) return undefined;
    const started = m.report.startedUs;
    const elapsed = Math.min(untilUs - started, m.limitUs);
    const target = this.#stepsBy(m, elapsed);
    const odometry = this.#odometry;
    while (odometry.masterSteps < target) {
      if (odometry.masterSteps + 1 < this.#checkStep) {
        this.#walk(m, Math.min(target, this.#checkStep - 1));
      } else if (!this.#checkedStep(m)) {
        return 'collision';
      }
    }
    if (elapsed >= m.limitUs) {
      this.finish('done', Math.min(started + m.limitUs, untilUs));
      return 'done';
    }
    return 'running';
  }

  /**
   * Takes the steps due by `untilUs` that need no check (for a reader that wants the pose now;
   * the world handles the events). Never ends the motion.
   */
  catchUp(untilUs: number): void {
    const m = this.#motion;
    if (m === undefined) return;
    const elapsed = Math.min(untilUs - m.report.startedUs, m.limitUs);
    const target = Math.min(this.#stepsBy(m, elapsed), this.#checkStep - 1);
    if (target > this.#odometry.masterSteps) this.#walk(m, target);
  }

  /** Master steps made by `elapsed`: a drive makes only those due strictly before its limit. */
  #stepsBy(m: RunningMotion<C>, elapsed: number): number {
    if (elapsed <= 0) return 0;
    if (m.report.kind === 'drive' && elapsed >= m.limitUs) return m.lastStep;
    return m.plan.masterStepsAt(elapsed);
  }

  #walk(m: RunningMotion<C>, k: number): void {
    const odometry = this.#odometry;
    const left = odometry.left;
    const right = odometry.right;
    odometry.walkTo(k);
    m.report.doneLeft += odometry.left - left;
    m.report.doneRight += odometry.right - right;
  }

  /** The next step, checked: taken (true), or the motion ends in a collision (false). */
  #checkedStep(m: RunningMotion<C>): boolean {
    const odometry = this.#odometry;
    const k = odometry.masterSteps + 1;
    const atUs = m.report.startedUs + m.plan.masterStepTimeUs(k);
    const next = this.#scratch;
    odometry.peek(next);
    const contact = blockingContact(this.#contactTest, this.#radius, odometry.pose, next);
    if (contact !== undefined) {
      m.report.contact = contact;
      this.finish('collision', atUs);
      return false;
    }
    this.#walk(m, k);
    this.#measureRoom(m, k, atUs);
    return true;
  }

  /** After step k (at `atUs`): which later steps are sure to touch nothing. */
  #measureRoom(m: RunningMotion<C>, k: number, atUs: number): void {
    if (this.#freeSpace === undefined) {
      this.#checkStep = k + 1;
      return;
    }
    const room = this.#freeSpace(
      this.#odometry.xCm / 100,
      this.#odometry.yCm / 100,
      this.#radius,
      atUs,
    );
    const stepCm = this.#odometry.maxStepCm;
    const free = room.distance - CLEARANCE_MARGIN_M;
    // Steps by distance: the centre moves at most `stepCm` per master step.
    const byDistance =
      stepCm === 0
        ? Number.POSITIVE_INFINITY
        : free <= 0
          ? k
          : k + Math.floor((free * 100) / stepCm);
    // Steps by time: only the steps strictly before `untilUs`.
    const byTime = Number.isFinite(room.untilUs)
      ? Math.max(k, m.plan.masterStepsAt(room.untilUs - 1 - m.report.startedUs))
      : Number.POSITIVE_INFINITY;
    this.#checkStep = Math.min(byDistance, byTime) + 1;
  }

  #start(
    plan: StepPlan,
    limitUs: number,
    nowUs: number,
    config: RobotConfig,
    fields: MotionFields,
  ): MotionHandle<C> {
    this.finish('replaced', nowUs);
    const report: MotionReport<C> = {
      moveId: this.#nextMoveId,
      ...fields,
      durationUs: limitUs,
      doneLeft: 0,
      doneRight: 0,
      startedUs: nowUs,
      endedUs: undefined,
      outcome: 'running',
    };
    this.#nextMoveId += 1;
    let settle: (r: MotionReport<C>) => void = () => undefined;
    const finished = new Promise<MotionReport<C>>((resolve) => {
      settle = resolve;
    });
    const lastStep =
      report.kind === 'move'
        ? plan.masterTerm
        : Number.isFinite(limitUs)
          ? limitUs <= 0
            ? 0
            : plan.masterStepsAt(limitUs - 1)
          : Number.POSITIVE_INFINITY;
    this.#motion = { plan, report, limitUs, lastStep, settle };
    const scales = this.#body?.nextMotion();
    this.#syncReported();
    this.#countedWith = config;
    this.#reported?.beginMotion(scales?.reported ?? { left: 1, right: 1 });
    this.#odometry.begin(plan, config, scales?.truth);
    this.#checkStep = 1;
    this.#onChange();
    if (limitUs <= 0) this.finish('done', nowUs);
    return { report, finished };
  }
}
