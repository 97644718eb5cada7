import type { EvalAgent, ModelFailure } from './agent.js';
import { EvalError } from './errors.js';
import { RealitySchema } from './reality.js';
import { summariseGroups, summariseTasks } from './scores.js';
import type { GroupSummary, RateOverTasks, TaskSummary } from './scores.js';
import type { PassK } from './pass-k.js';
import { runRobotTrial, runsOnRobot } from './robot-trial.js';
import type { EvalRobot } from './robot-trial.js';
import type { Task } from './task-schema.js';
import { runTrial } from './trial.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial.js';

/**
 * The version of the report's JSON shape (2: the trials and agents whose model failed; 3: the
 * interval of the overall and group rates is a bootstrap over tasks, `tasks` and `interval` on
 * those rates, `passK` and `usesGroundTruth` per agent).
 */
export const REPORT_VERSION = 3;

/** An agent whose model could not be used: in how many trials, and the first failure. */
export interface AgentModelFailure extends ModelFailure {
  /** Trials that ran and in which the model never answered. */
  trials: number;
  /**
   * Trials not run at all: once the model failed before it had answered in any trial, the
   * agent's remaining trials are skipped (each would only wait out the same failure).
   */
  notRun: number;
}

/** One agent's scores (on one robot: the simulator, or a robot of {@link EvalOptions.robots}). */
export interface AgentScores {
  /** The agent's name; on a robot, `NAME@ROBOT`. */
  agent: string;
  /** `simulator` (scored from its ground truth), or the robot's name (from its reports). */
  on: string;
  /**
   * Whether the agent was given the ground truth (it declares `usesGroundTruth`): an oracle, a
   * reference to compare with, not an agent under test.
   */
  usesGroundTruth: boolean;
  /**
   * Over the scored trials only: those whose model failed are not among them. Its interval is a
   * bootstrap over the tasks (see `intervalOverTasks`).
   */
  overall: RateOverTasks;
  /** pass^k for k = 1 to the trials per task, over the tasks with a scored trial. */
  passK: PassK[];
  groups: GroupSummary[];
  tasks: TaskSummary[];
  /** Every trial run, those whose model failed included. */
  trials: TrialScore[];
  /**
   * Set when the agent's model could not be used in some trials (it never answered): the run is
   * then a failure of the model, not a score. Null when the model answered in every trial.
   */
  modelFailure: AgentModelFailure | null;
}

/**
 * An evaluation's report. `scores` is deterministic given the tasks, the seed and deterministic
 * agents (two runs give byte-identical JSON); `timing` holds the wall-clock figures, never the
 * same twice, apart from it.
 */
export interface EvalReport {
  version: number;
  scores: { seed: number; trialsPerTask: number; tasks: string[]; agents: AgentScores[] };
  timing: {
    agents: {
      agent: string;
      wallMs: number;
      modelMs: number;
      trials: (TrialTiming & { task: string; seed: number })[];
    }[];
  };
}

/** Options of {@link runEval}. */
export interface EvalOptions extends TrialOptions {
  tasks: readonly Task[];
  agents: readonly EvalAgent[];
  /** Trials per task (k); trial i runs with seed `seed + i`. Default 5. */
  trials?: number;
  /** Default 1. */
  seed?: number;
  /** Trials run at once in the simulator. Default 1. */
  concurrency?: number;
  /**
   * Robots to run the same agents on as well, after the simulator: each of the tasks that
   * {@link runsOnRobot} on it (all of them on a robot staged in each task's world; else the
   * precision group, judged from the robot's own reports), one trial at a time per robot. Their rows sit beside the simulator's, named `AGENT@ROBOT`.
   */
  robots?: readonly EvalRobot[];
  /** Whether the agents run in the simulator too (`false`: on the robots only). Default true. */
  simulator?: boolean;
  /**
   * Told of every trial as it ends (in the order they end). `total` is the trials still to be
   * run plus those done: it drops when an agent whose model failed has its trials skipped.
   */
  onTrial?: (event: {
    agent: string;
    score: TrialScore;
    timing: TrialTiming;
    done: number;
    total: number;
  }) => void;
}

function whole(name: string, value: number, min: number, max: number): number {
  if (!Number.isInteger(value) || value < min || value > max)
    throw new EvalError(
      'CONFIG',
      `"${name}" must be a whole number from ${min} to ${max}, got ${value}`,
    );
  return value;
}

/** Runs every agent on every task k times and scores them. */
export async function runEval(options: EvalOptions): Promise<EvalReport> {
  const trials = whole('trials', options.trials ?? 5, 1, 1000);
  const seed = whole('seed', options.seed ?? 1, 0, 2 ** 31 - 1);
  const concurrency = whole('concurrency', options.concurrency ?? 1, 1, 64);
  if (options.reality !== undefined) {
    const parsed = RealitySchema.safeParse(options.reality);
    if (!parsed.success) {
      const issue = parsed.error.issues[0];
      throw new EvalError(
        'CONFIG',
        `"reality.${issue?.path.map(String).join('.') ?? ''}" ${issue?.message ?? 'is invalid'}`,
      );
    }
  }
  if (options.tasks.length === 0) throw new EvalError('CONFIG', 'no tasks to run');
  if (options.agents.length === 0) throw new EvalError('CONFIG', 'no agents to run');
  const robots = options.robots ?? [];
  const tasksOn = (robot: EvalRobot) => options.tasks.filter((t) => runsOnRobot(t, robot));
  if (options.simulator === false && robots.length === 0)
    throw new EvalError('CONFIG', 'no simulator and no robot to run on');
  const idle = robots.find((robot) => tasksOn(robot).length === 0);
  if (idle !== undefined)
    throw new EvalError(
      'CONFIG',
      `none of the tasks can run on ${idle.name}: only those judged from its reports can (the precision group)`,
    );
  // one row per agent and place: the simulator's first, then each robot's
  const rows = [
    ...(options.simulator === false ? [] : options.agents).map((agent) => ({
      agent,
      name: agent.name,
      robot: undefined,
    })),
    ...robots.flatMap((robot) =>
      options.agents.map((agent) => ({ agent, name: `${agent.name}@${robot.name}`, robot })),
    ),
  ];
  const jobs = rows.flatMap((row, a) =>
    (row.robot === undefined ? options.tasks : tasksOn(row.robot)).flatMap((task) =>
      Array.from({ length: trials }, (_, i) => ({
        a,
        agent: row.agent,
        name: row.name,
        robot: row.robot,
        task,
        seed: seed + i,
        trial: i,
      })),
    ),
  );
  const results: ({ score: TrialScore; timing: TrialTiming } | undefined)[] = new Array(
    jobs.length,
  );
  let next = 0;
  let done = 0;
  // per row: whether its model answered in some trial, its first failure, and trials skipped
  const reached = rows.map(() => false);
  const firstFailure: (ModelFailure | undefined)[] = rows.map(() => undefined);
  const skipped = rows.map(() => 0);
  const skippedTotal = () => skipped.reduce((a, b) => a + b, 0);
  const {
    tasks: _t,
    agents: _a,
    trials: _k,
    seed: _s,
    concurrency: _c,
    robots: _r,
    simulator: _sim,
    onTrial,
    ...trialOptions
  } = options;
  const simulated = jobs.flatMap((job, i) => (job.robot === undefined ? [i] : []));
  async function run(i: number): Promise<void> {
    const job = jobs[i] as (typeof jobs)[number];
    // a model that failed before it ever answered is not tried again
    if (firstFailure[job.a] !== undefined && !reached[job.a]) {
      skipped[job.a] = (skipped[job.a] ?? 0) + 1;
      return;
    }
    const perTrial = { ...trialOptions, trial: job.trial };
    const result =
      job.robot === undefined
        ? await runTrial(job.task, job.seed, job.agent, perTrial)
        : await runRobotTrial(job.task, job.seed, job.agent, job.robot, perTrial);
    results[i] = result;
    const failure = result.score.modelFailure;
    if (failure === null) reached[job.a] = true;
    else firstFailure[job.a] ??= failure;
    done += 1;
    onTrial?.({ agent: job.name, ...result, done, total: jobs.length - skippedTotal() });
  }
  async function worker(): Promise<void> {
    for (let n = next++; n < simulated.length; n = next++) await run(simulated[n] as number);
  }
  await Promise.all(
    Array.from({ length: Math.min(concurrency, simulated.length) }, () => worker()),
  );
  // then the robots, one trial at a time each (one robot, one session): after the simulator,
  // whose CPU work would otherwise hold up the robots' clocks
  await Promise.all(
    robots.map(async (robot) => {
      for (const [i, job] of jobs.entries()) if (job.robot === robot) await run(i);
    }),
  );

  const agents: AgentScores[] = [];
  const timing: EvalReport['timing']['agents'] = [];
  rows.forEach((row, a) => {
    const mine = jobs.flatMap((job, i) =>
      job.a === a && results[i] !== undefined ? [{ job, result: results[i] }] : [],
    );
    const scores = mine.map((m) => m.result.score);
    const scored = scores.filter((t) => t.modelFailure === null);
    const failed = scores.filter((t) => t.modelFailure !== null);
    const first = failed[0]?.modelFailure;
    agents.push({
      agent: row.name,
      on: row.robot?.name ?? 'simulator',
      usesGroundTruth: row.agent.usesGroundTruth === true,
      ...summariseGroups(scored),
      tasks: summariseTasks(scored),
      trials: scores,
      modelFailure:
        first === undefined || first === null
          ? null
          : { ...first, trials: failed.length, notRun: skipped[a] ?? 0 },
    });
    const times = mine.map((m) => ({ task: m.job.task.id, seed: m.job.seed, ...m.result.timing }));
    timing.push({
      agent: row.name,
      wallMs: times.reduce((s, t) => s + t.wallMs, 0),
      modelMs: times.reduce((s, t) => s + t.modelMs, 0),
      trials: times,
    });
  });
  return {
    version: REPORT_VERSION,
    scores: { seed, trialsPerTask: trials, tasks: options.tasks.map((t) => t.id), agents },
    timing: { agents: timing },
  };
}
