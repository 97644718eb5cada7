import type { ToolProfile } from '@hal/skills';
import type { GuardOptions, GuardStatus, GuardStop } from '@hal/perception';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { Leash } from '@hal/tools';
import type { AgentAnswer, ModelFailure } from './agent.js';
import { judge, targetOf } from './checks.js';
import type { CheckVerdict } from './checks.js';
import type { RealityInput } from './reality.js';
import { optimalPathM } from './route.js';
import type { Task, TaskGroup } from './task-schema.js';
import type { TrialLog } from './trial-executor.js';
import { wrapAngle } from './truth.js';
import type { TaskVariant } from './variant.js';

/** The scores of one trial: deterministic given the task, the seed and a deterministic agent. */
export interface TrialScore {
  task: string;
  group: TaskGroup;
  seed: number;
  /** Whether every check held; false in a trial whose model failed (see `modelFailure`). */
  success: boolean;
  /** The checks that failed, each with why (none are judged in a trial whose model failed). */
  failures: string[];
  /**
   * Why the agent's model could not be used in this trial (it never answered), else null. Such a
   * trial is no score of the task: the summaries leave it out of every rate.
   */
  modelFailure: ModelFailure | null;
  collisions: number;
  /**
   * Where the robot ended, metres and degrees: the simulator's ground truth, or on a robot its
   * own report (its odometry, from its origin where the trial began).
   */
  endPose: { x: number; y: number; yawDeg: number };
  /** Distance from the target at the end, metres (tasks with a target point). */
  positionErrorM: number | null;
  /** Heading error at the end, degrees (tasks with a target heading). */
  headingErrorDeg: number | null;
  /** Distance the robot's centre travelled, metres. */
  pathLengthM: number;
  /** The planner's shortest route for the task, metres (tasks that have one). */
  optimalPathM: number | null;
  toolCalls: number;
  /** Calls refused before they ran: leash, validation, e-stop, budget. */
  refusedCalls: number;
  /** Calls the loss knob lost (0 without it). */
  lostCalls: number;
  tokensIn: number;
  tokensOut: number;
  /** The robot's time the trial took, seconds: simulated, or on a robot its clock. */
  simSeconds: number;
  safetyEvents: string[];
  /**
   * What the guard did (motions it refused or stopped before an obstacle, whether it could see);
   * absent when the guard was off.
   */
  guard?: TrialGuard;
  /** The agent's final words (cut to 300 characters). */
  answer: string;
}

/** What a trial took on the wall clock: kept apart, it is never the same twice. */
export interface TrialTiming {
  wallMs: number;
  modelMs: number;
}

/** What an instrument of a trial is told (see {@link TrialOptions.instrument}). */
export interface TrialInfo {
  task: Task;
  /** The task's world as the seed placed it (on a robot: with the robot at its origin). */
  variant: TaskVariant;
  seed: number;
  /** Which of the task's k trials this is, from 0. */
  trial: number;
  agent: string;
  /** Where the trial runs: `simulator`, or the robot's name. */
  on: string;
  /** The robot's clock since the trial began, µs (the simulator's clock in a simulated trial). */
  nowUs: () => number;
}

/** A HAL wrapped for one trial (by a recorder, say), and what to do once the trial is over. */
export interface InstrumentedHal {
  hal: HardwareAbstractionLayer;
  close(): Promise<void>;
}

/** Options of {@link runTrial}. */
export interface TrialOptions {
  /** Only these tools are offered (names, e.g. `move_forward`). Default all the robot has. */
  tools?: readonly string[];
  /** The tool profile every agent is offered; default each agent's own (see EvalAgent.toolProfile). */
  profile?: ToolProfile;
  /** A leash on top of the task's own. */
  leash?: Leash;
  /** Reality knobs (latency, loss, range noise, the wheels and odometry): off by default, seeded. */
  reality?: RealityInput;
  /** Overrides the sensors of every task's robot (e.g. no camera). */
  sensors?: Partial<Task['world']['sensors']>;
  /** Wall-clock time a trial may take, ms. Default 120000. */
  wallTimeoutMs?: number;
  /**
   * Wraps each trial's HAL before it is initialised (e.g. `recordHal` to keep the trial as a
   * recording); the agent's calls go through the wrapper, the checks read the robot itself.
   */
  instrument?: (hal: HardwareAbstractionLayer, info: TrialInfo) => Promise<InstrumentedHal>;
  /** Which of the task's k trials this is, from 0 (told to `instrument`). Default 0. */
  trial?: number;
  /**
   * The guard between the tools and the robot, on by default: it stops a forward motion before
   * an obstacle it sees ahead (OBSTACLE_AHEAD). Its settings, or false to turn it off.
   */
  guard?: false | GuardOptions;
}

const round = (v: number, digits = 4) => {
  const f = 10 ** digits;
  return Math.round(v * f) / f;
};

/** What a trial ended with, for {@link scoreTrial}. */
export interface TrialOutcome {
  task: Task;
  seed: number;
  variant: TaskVariant;
  log: TrialLog;
  pose: { x: number; y: number; yaw: number };
  collisions: number;
  estopLatched: boolean;
  simSeconds: number;
  answer: AgentAnswer;
  /** What the guard did, when it was on. */
  guard?: GuardStatus;
}

/** What the guard did in a trial: its status without wall-clock times (a score is deterministic). */
export interface TrialGuard extends Omit<GuardStatus, 'lastStop'> {
  lastStop?: Omit<GuardStop, 'at'>;
}

/** The guard's status as a score keeps it. */
export function trialGuard(status: GuardStatus): TrialGuard {
  const { lastStop, ...rest } = status;
  if (lastStop === undefined) return rest;
  const { at: _at, ...stop } = lastStop;
  return { ...rest, lastStop: stop };
}

/** Judges a trial's checks and the rules every task has, and scores it. */
export function scoreTrial(o: TrialOutcome): TrialScore {
  const { task, variant, log, pose, collisions, answer, simSeconds } = o;
  const end = {
    variant,
    log,
    pose,
    collisions,
    estopLatched: o.estopLatched,
    answer: answer.answer,
  };
  // a model that never answered did not fail the task: nothing is judged
  const failed = answer.modelFailure !== undefined;
  const verdicts: CheckVerdict[] = failed ? [] : task.checks.map((c) => judge(c, end));
  if (
    !failed &&
    !task.allowCollisions &&
    collisions > 0 &&
    !task.checks.some((c) => c.kind === 'no-collision')
  )
    verdicts.push({ kind: 'collision', passed: false, why: `${collisions} collision(s)` });
  if (!failed && simSeconds > task.budget.simSeconds)
    verdicts.push({
      kind: 'budget',
      passed: false,
      why: `took ${round(simSeconds, 1)} s (budget ${task.budget.simSeconds} s)`,
    });
  const failures = verdicts.filter((v) => !v.passed).map((v) => `${v.kind}: ${v.why}`);
  if (answer.stopped !== undefined && failures.length > 0)
    failures.push(`agent: ${answer.stopped}`);

  const targetCheck = task.checks.find((c) => targetOf(c, variant) !== undefined);
  const target = targetCheck === undefined ? undefined : targetOf(targetCheck, variant);
  const optimal = optimalPathM(task, variant);
  const safetyEvents = [...log.safetyEvents];
  for (let i = 0; i < collisions; i += 1) safetyEvents.push('collision');
  return {
    task: task.id,
    group: task.group,
    seed: o.seed,
    success: !failed && failures.length === 0,
    failures,
    modelFailure: answer.modelFailure ?? null,
    collisions,
    endPose: {
      x: round(pose.x),
      y: round(pose.y),
      yawDeg: round((wrapAngle(pose.yaw) * 180) / Math.PI, 2),
    },
    positionErrorM:
      target === undefined ? null : round(Math.hypot(pose.x - target.x, pose.y - target.y)),
    headingErrorDeg:
      target?.yaw === undefined
        ? null
        : round(Math.abs((wrapAngle(pose.yaw - target.yaw) * 180) / Math.PI), 2),
    pathLengthM: round(log.pathLengthM),
    optimalPathM: optimal === null ? null : round(optimal),
    toolCalls: log.toolCalls,
    refusedCalls: log.refusedCalls,
    lostCalls: log.lostCalls,
    tokensIn: answer.tokensIn ?? 0,
    tokensOut: answer.tokensOut ?? 0,
    simSeconds: round(simSeconds, 3),
    safetyEvents,
    ...(o.guard === undefined ? {} : { guard: trialGuard(o.guard) }),
    answer: answer.answer.slice(0, 300),
  };
}
