import type { TrialScore } from './trial.js';
import type { TaskGroup } from './task-schema.js';

/** A proportion with its 95 % Wilson score interval. */
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
 * approximation it stays inside [0, 1] and is not empty at 0 or k successes of k.
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
  const z2 = z * z;
  const centre = (p + z2 / (2 * trials)) / (1 + z2 / trials);
  const half =
    (z / (1 + z2 / trials)) * Math.sqrt((p * (1 - p)) / trials + z2 / (4 * trials * trials));
  return {
    successes,
    trials,
    rate: round(p),
    low: round(Math.max(0, centre - half)),
    high: round(Math.min(1, centre + half)),
  };
}

/** One task's scores over its k trials. */
export interface TaskSummary {
  task: string;
  group: TaskGroup;
  success: Rate;
  /** Whether all k trials succeeded (pass^k). */
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
  success: Rate;
  /** Tasks of the group whose every trial succeeded. */
  passAllTasks: number;
}

/** Totals by group (in the order the groups first appear) and over everything. */
export function summariseGroups(trials: readonly TrialScore[]): {
  groups: GroupSummary[];
  overall: Rate;
} {
  const tasks = summariseTasks(trials);
  const groups: GroupSummary[] = [];
  for (const group of [...new Set(tasks.map((t) => t.group))]) {
    const mine = trials.filter((t) => t.group === group);
    const mineTasks = tasks.filter((t) => t.group === group);
    groups.push({
      group,
      tasks: mineTasks.length,
      success: wilson(mine.filter((t) => t.success).length, mine.length),
      passAllTasks: mineTasks.filter((t) => t.passAll).length,
    });
  }
  return { groups, overall: wilson(trials.filter((t) => t.success).length, trials.length) };
}
