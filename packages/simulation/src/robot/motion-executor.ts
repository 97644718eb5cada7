import { integrateOdometry, MovePlan, VelocityPlan } from '@hal/kinematics';
import type { PlanarPose, StepPlan } from '@hal/kinematics';
import type { RobotConfig } from '@hal/types';
import { blockingContact } from './contact.js';
import type { ContactTest } from './contact.js';
import type { MotionHandle, MotionReport, MoveOutcome } from './motion-report.js';

interface RunningMotion {
  plan: StepPlan;
  report: MotionReport;
  /** Stop at this elapsed time, µs (a move's last step, a drive's duration, or Infinity). */
  limitUs: number;
  settle: (report: MotionReport) => void;
}

type MotionFields = Pick<
  MotionReport,
  'kind' | 'plannedLeft' | 'plannedRight' | 'leftSps' | 'rightSps' | 'speed' | 'speedClamped'
>;

/**
 * The robot's motion state: at most one running motion (a {@link MovePlan} or a
 * {@link VelocityPlan}), the last one, the pose and the absolute wheel positions. It executes
 * the steps a plan has made by a given time and integrates odometry over them, as the firmware's
 * motion task does, stopping before a step that would bring its footprint into contact.
 */
export class MotionExecutor {
  /** Footprint radius, metres. */
  readonly #radius: number;
  #contactTest: ContactTest = () => undefined;
  #pose: PlanarPose;
  #left = 0;
  #right = 0;
  #motion: RunningMotion | undefined;
  #last: MotionReport | undefined;
  #nextMoveId = 1;

  constructor(start: PlanarPose, radius: number) {
    this.#pose = start;
    this.#radius = radius;
  }

  /** How the robot learns what it touches (the world sets it). */
  setContactTest(test: ContactTest): void {
    this.#contactTest = test;
  }

  get pose(): PlanarPose {
    return this.#pose;
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
  /** When the running motion's next event (its end) is due, µs, or Infinity. */
  get endUs(): number {
    const m = this.#motion;
    return m === undefined ? Number.POSITIVE_INFINITY : m.report.startedUs + m.limitUs;
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
  ): MotionHandle {
    const plan = new MovePlan(left, right, speed, config.accelerationStepsPerS2);
    return this.#start(plan, plan.durationUs, nowUs, {
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
  ): MotionHandle {
    const plan = new VelocityPlan(left, right, config.accelerationStepsPerS2);
    const limitUs = durationMs === undefined ? Number.POSITIVE_INFINITY : durationMs * 1000;
    return this.#start(plan, limitUs, nowUs, {
      kind: 'drive',
      plannedLeft: 0,
      plannedRight: 0,
      leftSps: left,
      rightSps: right,
      speed: Math.max(Math.abs(left), Math.abs(right)),
      speedClamped: clamped,
    });
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
    return true;
  }

  /**
   * Executes the steps the running motion has made by `untilUs` and integrates odometry over
   * them (with `config`'s geometry). Ends the motion `done` at its limit, or `collision` (at
   * `untilUs`, no step taken) when the new pose would be a collision. Returns the motion's outcome
   * (`running` if it goes on), or undefined when no motion is running.
   */
  stepTo(untilUs: number, config: RobotConfig): MoveOutcome | undefined {
    const m = this.#motion;
    if (m === undefined) return undefined;
    const started = m.report.startedUs;
    const elapsed = Math.min(untilUs - started, m.limitUs);
    // A drive makes only the steps due strictly before its duration (the firmware queues no step
    // at or after the limit); a move's limit is the time of its last step, which it makes.
    const steps = m.plan.stepsAt(
      m.report.kind === 'drive' && elapsed >= m.limitUs ? m.limitUs - 1 : elapsed,
    );
    const dl = steps.left - m.report.doneLeft;
    const dr = steps.right - m.report.doneRight;
    if (dl !== 0 || dr !== 0) {
      const next = integrateOdometry(this.#pose, dl, dr, config);
      const contact = blockingContact(this.#contactTest, this.#radius, this.#pose, next);
      if (contact !== undefined) {
        m.report.contact = contact;
        this.finish('collision', untilUs);
        return 'collision';
      }
      this.#pose = next;
      this.#left += dl;
      this.#right += dr;
      m.report.doneLeft = steps.left;
      m.report.doneRight = steps.right;
    }
    if (elapsed >= m.limitUs) {
      this.finish('done', Math.min(started + m.limitUs, untilUs));
      return 'done';
    }
    return 'running';
  }

  #start(plan: StepPlan, limitUs: number, nowUs: number, fields: MotionFields): MotionHandle {
    this.finish('replaced', nowUs);
    const report: MotionReport = {
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
    let settle: (r: MotionReport) => void = () => undefined;
    const finished = new Promise<MotionReport>((resolve) => {
      settle = resolve;
    });
    this.#motion = { plan, report, limitUs, settle };
    if (limitUs <= 0) this.finish('done', nowUs);
    return { report, finished };
  }
}
