import { SeededRandom } from '@hal/simulation';

/** One task's scored trials: how many succeeded of how many. */
export interface TaskCount {
  successes: number;
  trials: number;
}

/** Resamples of the bootstrap over tasks. */
export const BOOTSTRAP_RESAMPLES = 2000;
/** The bootstrap's fixed seed: the same report gives the same interval, run after run. */
export const BOOTSTRAP_SEED = 1;

const round = (v: number) => Math.round(v * 10_000) / 10_000;

/**
 * The Wilson score bounds of a proportion `p` observed over `n` draws (z = 1.96, 95 %): unlike
 * the normal approximation they stay inside [0, 1] and are not empty at p = 0 or 1.
 */
export function wilsonBounds(p: number, n: number, z = 1.96): { low: number; high: number } {
  if (n === 0) return { low: 0, high: 1 };
  const z2 = z * z;
  const centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const half = (z / (1 + z2 / n)) * Math.sqrt((p * (1 - p)) / n + z2 / (4 * n * n));
  return { low: round(Math.max(0, centre - half)), high: round(Math.min(1, centre + half)) };
}

/** Checks the counts; a task with no scored trial has no rate and is refused. */
export function checkCounts(tasks: readonly TaskCount[], what: string): void {
  for (const t of tasks)
    if (
      !Number.isInteger(t.trials) ||
      t.trials < 1 ||
      !Number.isInteger(t.successes) ||
      t.successes < 0 ||
      t.successes > t.trials
    )
      throw new RangeError(
        `${what}: each task needs 0 <= successes <= trials, integers, trials >= 1; got ${t.successes} of ${t.trials}`,
      );
}

/** The q-quantile of sorted values, linearly interpolated between neighbours. */
function quantile(sorted: readonly number[], q: number): number {
  const at = q * (sorted.length - 1);
  const below = Math.floor(at);
  const a = sorted[below] as number;
  const b = sorted[Math.min(below + 1, sorted.length - 1)] as number;
  return a + (b - a) * (at - below);
}

/** How a rate's interval over tasks was found (see {@link intervalOverTasks}). */
export type TaskIntervalMethod = 'bootstrap-tasks' | 'wilson-tasks';

/** Options of {@link intervalOverTasks}. */
export interface IntervalOptions {
  /** Default {@link BOOTSTRAP_RESAMPLES}. */
  resamples?: number;
  /** Default {@link BOOTSTRAP_SEED}. */
  seed?: number;
}

/**
 * The 95 % interval of a success rate over tasks, each task scored over its own trials. The
 * trials of one task are not independent (an agent tends to pass or fail every seed of a task
 * alike), so the tasks are what is sampled: the percentile bootstrap draws the tasks with
 * replacement (seeded: the same counts always give the same interval), each drawn task bringing
 * its own trials, and takes the 2.5th and 97.5th percentiles of the pooled rate of the draws
 * (with the same number of trials per task, the mean of the drawn tasks' rates).
 *
 * Where every task scored the same rate there is nothing to resample (the bootstrap would give
 * the point, e.g. 100 %-100 %); then each task counts as one observation of that rate and the
 * interval is Wilson's over the number of tasks (`wilson-tasks`). No task: 0 to 1.
 */
export function intervalOverTasks(
  tasks: readonly TaskCount[],
  options: IntervalOptions = {},
): { low: number; high: number; method: TaskIntervalMethod } {
  checkCounts(tasks, 'intervalOverTasks');
  const resamples = options.resamples ?? BOOTSTRAP_RESAMPLES;
  if (!Number.isInteger(resamples) || resamples < 1)
    throw new RangeError(`"resamples" must be a whole number of 1 or more, got ${resamples}`);
  const n = tasks.length;
  if (n === 0) return { low: 0, high: 1, method: 'wilson-tasks' };
  const rates = tasks.map((t) => t.successes / t.trials);
  const first = rates[0] as number;
  if (rates.every((r) => r === first)) return { ...wilsonBounds(first, n), method: 'wilson-tasks' };
  const random = new SeededRandom(options.seed ?? BOOTSTRAP_SEED);
  const stats: number[] = new Array<number>(resamples);
  for (let r = 0; r < resamples; r += 1) {
    let successes = 0;
    let trials = 0;
    for (let i = 0; i < n; i += 1) {
      const task = tasks[Math.floor(random.next() * n)] as TaskCount;
      successes += task.successes;
      trials += task.trials;
    }
    stats[r] = successes / trials;
  }
  stats.sort((a, b) => a - b);
  return {
    low: round(quantile(stats, 0.025)),
    high: round(quantile(stats, 0.975)),
    method: 'bootstrap-tasks',
  };
}
