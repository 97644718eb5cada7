import type { ToolResult } from '@hal/tools';
import type { AgentAnswer, AgentTrial, EvalAgent } from '../agent.js';
import { targetOf, trueAnswer } from '../checks.js';
import { approachObject, planRoute } from '../route.js';
import type { Check } from '../task-schema.js';
import { gapAhead, wrapAngle } from '../truth.js';
import type { TaskVariant } from '../variant.js';

/** How often the oracle repeats a call that failed (a fault, a timeout) before it gives up. */
const ATTEMPTS = 8;

/** How often the oracle corrects a move the wheels did not make exactly (slip, diameter error). */
const CORRECTIONS = 3;

/** The legs of a drive to a point once the wheels are seen to curve, cm. */
const SHORT_LEG_CM = 25;
/** The most legs of one drive to a point. */
const MAX_LEGS = 40;

/** Thrown inside the oracle when the e-stop latched and the task says not to reset it. */
class Latched extends Error {}

/**
 * The scripted oracle: reads the task and the world's ground truth, plans with the navigation
 * planner, drives through the same tools as any agent, retries what fails, and answers from the
 * truth. It proves every task solvable and is the upper bound of every score.
 */
export function oracleAgent(): EvalAgent {
  return {
    name: 'oracle',
    usesGroundTruth: true,
    run: async (trial) => {
      const truth = trial.truth;
      if (truth === undefined) return { answer: 'no ground truth given', stopped: 'no truth' };
      return new OracleRun(trial, truth).run();
    },
  };
}

class OracleRun {
  readonly #trial: AgentTrial;
  readonly #truth: TaskVariant;
  readonly #resetAllowed: boolean;
  #pose = { x: 0, y: 0, yaw: 0 };
  /** The longest leg of a drive to a point, cm (shortened when the wheels curve). */
  #legCm = 100;

  constructor(trial: AgentTrial, truth: TaskVariant) {
    this.#trial = trial;
    this.#truth = truth;
    this.#resetAllowed = truth.task.checks.some((c) => c.kind === 'estop' && !c.latched);
    this.#pose = { ...truth.start };
    this.#legCm = this.#chunkCm;
  }

  async run(): Promise<AgentAnswer> {
    const said: string[] = [];
    try {
      for (const check of this.#truth.task.checks) said.push(await this.#solve(check));
    } catch (error) {
      if (!(error instanceof Latched)) throw error;
    }
    const stopped = await this.#trial.execute({ name: 'is_emergency_stopped', arguments: {} });
    if (stopped.structured?.['emergencyStopped'] === true) {
      if (this.#resetAllowed) {
        await this.#trial.execute({ name: 'reset_emergency_stop', arguments: {} });
        said.push('The emergency stop engaged; I reset it as allowed.');
      } else {
        said.push('The emergency stop is engaged and latched; I did not reset it.');
      }
    }
    return { answer: said.filter((s) => s !== '').join(' ') || 'Done.' };
  }

  /** One call, repeated while it fails for a reason a retry can fix. */
  async #call(name: string, args: Record<string, unknown>): Promise<ToolResult> {
    let result: ToolResult | undefined;
    for (let attempt = 0; attempt < ATTEMPTS; attempt += 1) {
      result = await this.#trial.execute({ name, arguments: args });
      if (!result.isError) break;
      if (result.code === 'EMERGENCY_STOPPED') {
        if (!this.#resetAllowed) throw new Latched();
        await this.#trial.execute({ name: 'reset_emergency_stop', arguments: {} });
        continue;
      }
      if (result.code !== 'HARDWARE_ERROR' && result.code !== 'TIMEOUT') break;
    }
    this.#readPose();
    return result as ToolResult;
  }

  #readPose(): void {
    const pose = this.#trial.truePose?.();
    if (pose !== undefined) this.#pose = pose;
  }

  /** The longest straight move one call may make, cm (the leash's cap, else 1 m). */
  get #chunkCm(): number {
    const cap = this.#truth.task.leash?.maxDistanceM;
    return cap === undefined ? 100 : Math.floor(cap * 100 * 0.95);
  }

  async #forward(cm: number): Promise<void> {
    let left = cm;
    while (Math.abs(left) > 0.05) {
      const step = Math.sign(left) * Math.min(Math.abs(left), this.#chunkCm);
      const before = { ...this.#pose };
      await this.#call(step > 0 ? 'move_forward' : 'move_backward', { distanceCm: Math.abs(step) });
      const moved = Math.hypot(this.#pose.x - before.x, this.#pose.y - before.y) * 100;
      if (moved < 0.01) return; // blocked for good: leave it to the checks
      left -= Math.sign(step) * moved;
    }
  }

  /** Turns to `yaw`, and again while the wheels (a reality knob) left it more than 0.2° off. */
  async #turnTo(yaw: number): Promise<void> {
    for (let attempt = 0; attempt < CORRECTIONS; attempt += 1) {
      const turn = (wrapAngle(yaw - this.#pose.yaw) * 180) / Math.PI;
      if (Math.abs(turn) < 0.2) return;
      await this.#call('rotate', {
        direction: turn > 0 ? 'left' : 'right',
        degrees: Math.abs(turn),
      });
    }
  }

  /** Drives to (x, y) again while the body (a reality knob) ended more than 3 mm from it. */
  async #correctTo(x: number, y: number): Promise<void> {
    for (let attempt = 0; attempt < CORRECTIONS; attempt += 1) {
      if (Math.hypot(x - this.#pose.x, y - this.#pose.y) < 0.003) return;
      await this.#goTo(x, y);
    }
  }

  /**
   * Turns toward (x, y) and drives there, leg by leg. Wheels that are not what they seem (the
   * reality knobs) curve a straight move: once a leg ends more than 5 mm off its line, the legs
   * are cut to {@link SHORT_LEG_CM}, each aimed again from where the robot really is.
   */
  async #goTo(x: number, y: number): Promise<void> {
    for (let leg = 0; leg < MAX_LEGS; leg += 1) {
      const d = Math.hypot(x - this.#pose.x, y - this.#pose.y);
      if (d < 0.002) return;
      await this.#turnTo(Math.atan2(y - this.#pose.y, x - this.#pose.x));
      const from = { ...this.#pose };
      const aim = Math.atan2(y - from.y, x - from.x);
      const cm = Math.min(Math.hypot(x - from.x, y - from.y) * 100, this.#legCm);
      await this.#call('move_forward', { distanceCm: cm });
      const dx = this.#pose.x - from.x;
      const dy = this.#pose.y - from.y;
      if (Math.hypot(dx, dy) * 100 < 0.01) return; // blocked for good: leave it to the checks
      if (Math.abs(-Math.sin(aim) * dx + Math.cos(aim) * dy) > 0.005)
        this.#legCm = Math.min(this.#legCm, SHORT_LEG_CM);
    }
  }

  async #follow(
    waypoints: readonly { x: number; y: number }[],
    end: { x: number; y: number },
  ): Promise<void> {
    for (const w of waypoints.slice(1, -1)) await this.#goTo(w.x, w.y);
    await this.#goTo(end.x, end.y);
  }

  /** Drives to each stop in turn (beside an object, or to a point), then back if asked. */
  async #visit(check: Extract<Check, { kind: 'visit-in-order' }>): Promise<string> {
    const truth = this.#truth;
    for (const stop of check.stops) {
      if ('object' in stop) {
        const object = truth.objects.find((o) => o.name === stop.object);
        const approach = object && approachObject(truth.map, this.#pose, object, stop.withinM);
        if (approach === undefined) return 'No route.';
        await this.#follow(approach.plan.waypoints, approach.point);
      } else {
        const plan = planRoute(truth.map, this.#pose, stop);
        if (plan.status !== 'found') return `No route (${plan.status}).`;
        await this.#follow(plan.waypoints, stop);
      }
    }
    if (check.returnM === undefined) return 'Visited every stop.';
    const plan = planRoute(truth.map, this.#pose, truth.start);
    if (plan.status !== 'found') return `No route back (${plan.status}).`;
    await this.#follow(plan.waypoints, truth.start);
    return 'Visited every stop and came back.';
  }

  async #solve(check: Check): Promise<string> {
    const truth = this.#truth;
    switch (check.kind) {
      case 'displacement': {
        const target = targetOf(check, truth) as { x: number; y: number; yaw?: number };
        if (check.leftM === 0 && check.forwardM !== 0) await this.#forward(check.forwardM * 100);
        else await this.#goTo(target.x, target.y);
        await this.#correctTo(target.x, target.y);
        if (target.yaw !== undefined) await this.#turnTo(target.yaw);
        return 'Done.';
      }
      case 'return': {
        await this.#forward((check.minExcursionM + 0.05) * 100);
        await this.#goTo(truth.start.x, truth.start.y);
        await this.#correctTo(truth.start.x, truth.start.y);
        return 'Back at the start.';
      }
      case 'reach-point': {
        const plan = planRoute(truth.map, this.#pose, { x: check.x, y: check.y });
        if (plan.status !== 'found') return `No route (${plan.status}).`;
        await this.#follow(plan.waypoints, { x: check.x, y: check.y });
        return 'Reached the point.';
      }
      case 'reach-object': {
        const object = truth.objects.find((o) => o.name === check.object);
        if (object === undefined) return '';
        const approach = approachObject(truth.map, this.#pose, object, check.withinM);
        if (approach === undefined) return 'No route.';
        await this.#follow(approach.plan.waypoints, approach.point);
        return `Reached the ${check.object}.`;
      }
      case 'answer':
        return `The answer is ${trueAnswer(truth, check.question, check)}.`;
      case 'visit-in-order':
        return this.#visit(check);
      case 'stop-before': {
        const gap = gapAhead(truth.map, this.#pose.x, this.#pose.y, this.#pose.yaw);
        await this.#forward((gap - check.maxGapM / 2) * 100);
        return 'Stopped before it.';
      }
      case 'fence-respected': {
        const fence = truth.task.leash?.geofence;
        if (fence === undefined) return '';
        const margin = Math.min(0.05, check.approachM / 2);
        const x = Math.min(Math.max(check.x, fence.minX + margin), fence.maxX - margin);
        const y = Math.min(Math.max(check.y, fence.minY + margin), fence.maxY - margin);
        await this.#goTo(x, y);
        return 'Stopped at the geofence: the point is outside it.';
      }
      case 'estop':
      case 'no-collision':
        return '';
    }
  }
}
