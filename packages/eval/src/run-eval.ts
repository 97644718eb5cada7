import type { EvalAgent } from './agent.js';
import { EvalError } from './errors.js';
import { RealitySchema } from './reality.js';
import { summariseGroups, summariseTasks } from './scores.js';
import type { GroupSummary, Rate, TaskSummary } from './scores.js';
import type { Task } from './task-schema.js';
import { runTrial } from './trial.js';
import type { TrialOptions, TrialScore, TrialTiming } from './trial.js';

/** The version of the report's JSON shape. */
export const REPORT_VERSION = 1;

/** One agent's scores. */
export interface AgentScores {
  agent: string;
  overall: Rate;
  groups: GroupSummary[];
  tasks: TaskSummary[];
  trials: TrialScore[];
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
  /** Trials run at once. Default 1. */
  concurrency?: number;
  /** Told of every trial as it ends (in the order they end). */
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
  const jobs = options.agents.flatMap((agent, a) =>
    options.tasks.flatMap((task) =>
      Array.from({ length: trials }, (_, i) => ({ a, agent, task, seed: seed + i })),
    ),
  );
  const results: ({ score: TrialScore; timing: TrialTiming } | undefined)[] = new Array(
    jobs.length,
  );
  let next = 0;
  let done = 0;
  const {
    tasks: _t,
    agents: _a,
    trials: _k,
    seed: _s,
    concurrency: _c,
    onTrial,
    ...trialOptions
  } = options;
  async function worker(): Promise<void> {
    for (let i = next++; i < jobs.length; i = next++) {
      const job = jobs[i] as (typeof jobs)[number];
      const result = await runTrial(job.task, job.seed, job.agent, trialOptions);
      results[i] = result;
      done += 1;
      onTrial?.({ agent: job.agent.name, ...result, done, total: jobs.length });
    }
  }
  await Promise.all(Array.from({ length: Math.min(concurrency, jobs.length) }, () => worker()));

  const agents: AgentScores[] = [];
  const timing: EvalReport['timing']['agents'] = [];
  options.agents.forEach((agent, a) => {
    const mine = jobs.flatMap((job, i) =>
      job.a === a && results[i] !== undefined ? [{ job, result: results[i] }] : [],
    );
    const scores = mine.map((m) => m.result.score);
    agents.push({
      agent: agent.name,
      ...summariseGroups(scores),
      tasks: summariseTasks(scores),
      trials: scores,
    });
    const times = mine.map((m) => ({ task: m.job.task.id, seed: m.job.seed, ...m.result.timing }));
    timing.push({
      agent: agent.name,
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
