import { intervalOverTasks, wilsonBounds } from './interval.js';
import type { TaskCount, TaskIntervalMethod } from './interval.js';
import { passHatK } from './pass-k.js';
import type { PassK } from './pass-k.js';
import type { TrialScore } from './trial.js';
import type { TaskGroup } from './task-schema.js';

/**
 * A proportion with its 95 % interval. For one task's trials (independent draws of the task's
 * seed) it is the Wilson score interval; over tasks, see {@link RateOverTasks}.
 */
export interface Rate {
  successes: number;
  trials: number;
  rate: number;
  low: number;
  high: number;
}

const round = (v: number) => Math.round(v * 10_000) / 10_000;

/**
 * The Wilson score interval of `successes` out of `trials` (z = 1.96, 95 %): unlike the normal
 * approximation it stays inside [0, 1] and is not empty at 0 or k successes of k. It assumes the
 * trials independent: right for the trials of one task, too narrow for trials of many tasks.
 */
export function wilson(successes: number, trials: number, z = 1.96): Rate {
  if (
    !Number.isInteger(trials) ||
    trials < 0 ||
    !Number.isInteger(successes) ||
    successes < 0 ||
    successes > trials
  )
    throw new RangeError(
      `wilson: need 0 <= successes <= trials, integers; got ${successes} of ${trials}`,
    );
  if (trials === 0) return { successes, trials, rate: 0, low: 0, high: 1 };
  const p = successes / trials;
  return { successes, trials, rate: round(p), ...wilsonBounds(p, trials, z) };
}

/**
 * A success rate over several tasks, each run over its own trials, with the 95 % interval of
 * {@link intervalOverTasks}: the tasks, not the trials, are the sample (a bootstrap over tasks).
 */
export interface RateOverTasks extends Rate {
  /** Tasks the rate is over. */
  tasks: number;
  /**
   * How `low` and `high` were found: `bootstrap-tasks` (the percentile bootstrap over tasks), or
   * `wilson-tasks` where every task scored the same (Wilson's, each task one observation).
   */
  interval: TaskIntervalMethod;
}

/** The pooled rate of the tasks' trials, with the bootstrap interval over the tasks. */
export function rateOverTasks(tasks: readonly TaskCount[]): RateOverTasks {
  const successes = tasks.reduce((s, t) => s + t.successes, 0);
  const trials = tasks.reduce((s, t) => s + t.trials, 0);
  const { low, high, method } = intervalOverTasks(tasks);
  return {
    successes,
    trials,
    rate: trials === 0 ? 0 : round(successes / trials),
    low,
    high,
    tasks: tasks.length,
    interval: method,
  };
}

/** One task's scores over its k trials. */
export interface TaskSummary {
  task: string;
  group: TaskGroup;
  /** Over the task's trials, with the Wilson interval (its seeds are independent draws). */
  success: Rate;
  /** Whether all k trials succeeded. */
  passAll: boolean;
  collisions: number;
  meanPositionErrorM: number | null;
  meanPathRatio: number | null;
  toolCalls: number;
  refusedCalls: number;
  tokensIn: number;
  tokensOut: number;
  safetyEvents: number;
  /** Motions the guard refused or stopped before an obstacle (OBSTACLE_AHEAD), over the trials. */
  guardStops: number;
}

function mean(values: number[]): number | null {
  return values.length === 0 ? null : round(values.reduce((a, b) => a + b, 0) / values.length);
}

/** Sums a field of the trials. */
function sum(trials: readonly TrialScore[], pick: (t: TrialScore) => number): number {
  return trials.reduce((a, t) => a + pick(t), 0);
}

/** The per-task summaries, in the order the tasks first appear. */
export function summariseTasks(trials: readonly TrialScore[]): TaskSummary[] {
  const byTask = new Map<string, TrialScore[]>();
  for (const t of trials) byTask.set(t.task, [...(byTask.get(t.task) ?? []), t]);
  return [...byTask.values()].map((list) => {
    const first = list[0] as TrialScore;
    const successes = list.filter((t) => t.success).length;
    return {
      task: first.task,
      group: first.group,
      success: wilson(successes, list.length),
      passAll: successes === list.length,
      collisions: sum(list, (t) => t.collisions),
      meanPositionErrorM: mean(
        list.flatMap((t) => (t.positionErrorM === null ? [] : [t.positionErrorM])),
      ),
      meanPathRatio: mean(
        list.flatMap((t) =>
          t.optimalPathM === null || t.optimalPathM === 0 || !t.success
            ? []
            : [t.pathLengthM / t.optimalPathM],
        ),
      ),
      toolCalls: sum(list, (t) => t.toolCalls),
      refusedCalls: sum(list, (t) => t.refusedCalls),
      tokensIn: sum(list, (t) => t.tokensIn),
      tokensOut: sum(list, (t) => t.tokensOut),
      safetyEvents: sum(list, (t) => t.safetyEvents.length),
      guardStops: sum(list, (t) => t.guard?.stops ?? 0),
    };
  });
}

/** One group's totals for an agent. */
export interface GroupSummary {
  group: TaskGroup;
  tasks: number;
  /** Over the group's tasks, the interval a bootstrap over them. */
  success: RateOverTasks;
  /** Tasks of the group whose every trial succeeded. */
  passAllTasks: number;
}

/**
 * Totals by group (in the order the groups first appear) and over everything, each rate with its
 * interval over tasks, and pass^k over all the tasks for k = 1 to the trials per task.
 */
export function summariseGroups(trials: readonly TrialScore[]): {
  groups: GroupSummary[];
  overall: RateOverTasks;
  passK: PassK[];
} {
  const tasks = summariseTasks(trials);
  const counts = (list: readonly TaskSummary[]) =>
    list.map((t) => ({ successes: t.success.successes, trials: t.success.trials }));
  const groups: GroupSummary[] = [];
  for (const group of [...new Set(tasks.map((t) => t.group))]) {
    const mineTasks = tasks.filter((t) => t.group === group);
    groups.push({
      group,
      tasks: mineTasks.length,
      success: rateOverTasks(counts(mineTasks)),
      passAllTasks: mineTasks.filter((t) => t.passAll).length,
    });
  }
  return { groups, overall: rateOverTasks(counts(tasks)), passK: passHatK(counts(tasks)) };
}
