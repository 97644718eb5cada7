import { MovePlan, OdometryIntegrator, VelocityPlan } from '@hal/kinematics';
import type { StepPlan } from '@hal/kinematics';
import { normalizeAngle, stepsPerCm } from '@hal/types';
import type { Pose, RobotConfig } from '@hal/types';
import type { Command, MotionReply, StatusReply } from './protocol/schemas.js';

interface Prediction {
  plan: StepPlan;
  /** Host time the motion started, ms. */
  startedAt: number;
  /** Absolute counters when it started (as far as the host knows). */
  left: number;
  right: number;
  moveId: number;
  /** Robot-time duration cap (drive with a duration), µs. */
  capUs: number;
}

/** What the robot last reported of its wheels (see {@link PoseTracker.reported}). */
export interface ReportedSteps {
  /** The left wheel's absolute step counter since the robot started. */
  leftSteps: number;
  /** The right wheel's absolute step counter since the robot started. */
  rightSteps: number;
  /** The left wheel's speed, steps/s (0 when the robot reported it idle). */
  leftStepsPerS: number;
  /** The right wheel's speed, steps/s. */
  rightStepsPerS: number;
  /** The robot's uptime in its last status reply, ms. */
  robotUptimeMs: number;
}

const zero = (value: number): number => (value === 0 ? 0 : value);

/** Where the robot stands when the HAL connects, in the frame its poses are given in. */
export interface StartPose {
  /** Metres. */
  x: number;
  /** Metres. */
  y: number;
  /** Radians, counter-clockwise from +x. */
  yaw: number;
}

/**
 * Host-side dead reckoning: integrates the step counters of each status reply with the firmware's
 * odometry (@hal/kinematics), in a frame anchored where the robot was when the HAL connected
 * (origin, facing +x). Between status replies it predicts the counters from the running motion's
 * step plan, the firmware's own planner, so `getPose()` is right while a motion runs.
 *
 * A predicted pose says so (`confirmed: false`), and so does any pose once the link is lost. The
 * prediction never runs past the robot's host timeout after the robot was last heard from: by
 * then a robot that hears nothing from the host has stopped by itself, and one that lost power
 * stopped earlier still.
 */
export class PoseTracker {
  #config: RobotConfig;
  #odometry: OdometryIntegrator;
  #left = 0;
  #right = 0;
  #leftSps = 0;
  #rightSps = 0;
  #uptimeMs = -1;
  #prediction: Prediction | undefined;
  /** Host time of the robot's last reply, ms. */
  #heardAt: number;
  #linkUp = true;
  readonly #now: () => number;
  readonly #timeScale: number;

  constructor(config: RobotConfig, now: () => number, timeScale: number) {
    this.#config = config;
    this.#odometry = new OdometryIntegrator(config);
    this.#now = now;
    this.#timeScale = timeScale;
    this.#heardAt = now();
  }

  /** Uses a new geometry from now on (the pose so far is kept). */
  setConfig(config: RobotConfig): void {
    const pose = this.#odometry.pose;
    this.#config = config;
    this.#odometry = new OdometryIntegrator(config, pose, this.#left, this.#right);
  }

  /**
   * Makes the robot's present position `start` (metres and radians; default the origin, facing
   * +x): the frame every later pose is in.
   */
  anchor(status: StatusReply, start: StartPose = { x: 0, y: 0, yaw: 0 }): void {
    this.#odometry.reset(
      { xCm: start.x * 100, yCm: start.y * 100, headingRad: start.yaw },
      status.left_steps,
      status.right_steps,
    );
    this.#absorb(status);
  }

  /**
   * Integrates a status reply. If the robot restarted (its uptime went back), its counters began
   * again from zero: the pose is kept and integration resumes from the new counters.
   */
  update(status: StatusReply): void {
    if (status.uptime_ms < this.#uptimeMs) {
      this.#odometry.reset(this.#odometry.pose, status.left_steps, status.right_steps);
      this.#prediction = undefined;
    } else {
      this.#odometry.update(status.left_steps, status.right_steps);
    }
    this.#absorb(status);
  }

  /**
   * The wheel counters and speeds the robot itself last reported (a status or a stop reply),
   * never the prediction; undefined before the first status.
   */
  reported(): ReportedSteps | undefined {
    if (this.#uptimeMs < 0) return undefined;
    return {
      leftSteps: this.#left,
      rightSteps: this.#right,
      leftStepsPerS: this.#leftSps,
      rightStepsPerS: this.#rightSps,
      robotUptimeMs: this.#uptimeMs,
    };
  }

  /** Host time of the robot's last reply, ms (construction time before any reply). */
  get heardAt(): number {
    return this.#heardAt;
  }

  /** The link to the robot was lost (false) or is up again (true). */
  linkChanged(up: boolean): void {
    this.#linkUp = up;
  }

  /** Keeps the pose in step with a successful reply (any reply: the robot was heard from). */
  observe(cmd: Command, data: Record<string, unknown>): void {
    this.#heardAt = this.#now();
    if (!this.#linkUp && (cmd === 'stop' || cmd === 'estop')) {
      // a stop acknowledged while the link is down may come from a robot that restarted, whose
      // counters began again: only the status after reconnecting (with its uptime) is integrated
      this.motionStopped();
      return;
    }
    switch (cmd) {
      case 'get_status':
        this.update(data as unknown as StatusReply);
        break;
      case 'estop':
        // a 1.1 robot reports where the wheels stopped; a 1.0 one does not
        if (typeof data['left_steps'] === 'number' && typeof data['right_steps'] === 'number') {
          this.updateCounters(data['left_steps'], data['right_steps']);
        } else {
          this.motionStopped();
        }
        break;
      case 'stop':
        this.updateCounters(Number(data['left_steps']), Number(data['right_steps']));
        break;
      case 'move_cm':
      case 'move_steps':
      case 'rotate_deg':
      case 'drive':
        this.motionStarted(data as unknown as MotionReply);
        break;
    }
  }

  /** Counters reported by a `stop` reply. */
  updateCounters(left: number, right: number): void {
    this.#odometry.update(left, right);
    this.#left = left;
    this.#right = right;
    this.#leftSps = 0;
    this.#rightSps = 0;
    this.#prediction = undefined;
  }

  /** A motion command was accepted: predict its steps until a status says otherwise. */
  motionStarted(reply: MotionReply): void {
    const accel = this.#config.accelerationStepsPerS2;
    let plan: StepPlan | undefined;
    let capUs = Number.POSITIVE_INFINITY;
    if (reply.left_steps !== undefined && reply.right_steps !== undefined && reply.speed) {
      plan = new MovePlan(reply.left_steps, reply.right_steps, reply.speed, accel);
    } else if (reply.left_sps !== undefined && reply.right_sps !== undefined && reply.running) {
      plan = new VelocityPlan(Math.trunc(reply.left_sps), Math.trunc(reply.right_sps), accel);
      if (reply.duration_ms !== undefined) capUs = reply.duration_ms * 1000;
    }
    this.#prediction =
      plan === undefined
        ? undefined
        : {
            plan,
            startedAt: this.#now(),
            left: this.#left,
            right: this.#right,
            moveId: reply.move_id,
            capUs,
          };
  }

  /** Forgets the prediction (the motion was stopped). */
  motionStopped(): void {
    this.#prediction = undefined;
    this.#leftSps = 0;
    this.#rightSps = 0;
  }

  /** The pose now, REP-103, metres and radians; `confirmed: false` when it is predicted. */
  pose(): Pose {
    let pose = this.#odometry.pose;
    let leftSps = this.#leftSps;
    let rightSps = this.#rightSps;
    const p = this.#prediction;
    if (p !== undefined) {
      // robot time since the motion started, up to the robot's host timeout after it was last heard
      const robotUs = (hostMs: number) => hostMs * 1000 * this.#timeScale;
      const silentCapUs = robotUs(this.#heardAt - p.startedAt) + this.#config.hostTimeoutMs * 1000;
      const elapsedUs = Math.min(
        p.capUs,
        silentCapUs,
        Math.min(p.plan.durationUs, robotUs(this.#now() - p.startedAt)),
      );
      const steps = p.plan.stepsAt(elapsedUs);
      const left = p.left + steps.left;
      const right = p.right + steps.right;
      // never predict behind what a status already reported
      const ahead =
        Math.abs(left - p.left) >= Math.abs(this.#left - p.left) &&
        Math.abs(right - p.right) >= Math.abs(this.#right - p.right);
      if (ahead) {
        const predicted = new OdometryIntegrator(this.#config, pose, this.#left, this.#right);
        pose = predicted.update(left, right);
        const v =
          elapsedUs >= p.plan.durationUs || elapsedUs >= silentCapUs
            ? { left: 0, right: 0 }
            : p.plan.velocityAt(elapsedUs);
        leftSps = v.left;
        rightSps = v.right;
      }
    }
    const moving = p !== undefined || this.#leftSps !== 0 || this.#rightSps !== 0;
    const perCm = stepsPerCm(this.#config);
    const vl = leftSps / perCm / 100;
    const vr = rightSps / perCm / 100;
    return {
      position: { x: zero(pose.xCm / 100), y: zero(pose.yCm / 100), z: 0 },
      rotation: { yaw: zero(normalizeAngle(pose.headingRad)), pitch: 0, roll: 0 },
      velocity: {
        linear: zero((vl + vr) / 2),
        angular: zero((vr - vl) / (this.#config.wheelBaseCm / 100)),
      },
      confirmed: this.#linkUp && !moving,
    };
  }

  #absorb(status: StatusReply): void {
    this.#left = status.left_steps;
    this.#right = status.right_steps;
    this.#leftSps = status.running ? status.left_sps : 0;
    this.#rightSps = status.running ? status.right_sps : 0;
    this.#uptimeMs = status.uptime_ms;
    if (!status.running || (this.#prediction && status.move_id !== this.#prediction.moveId)) {
      this.#prediction = undefined;
    }
  }
}
