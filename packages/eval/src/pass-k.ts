import { checkCounts } from './interval.js';
import type { TaskCount } from './interval.js';

/** pass^k: the chance that k trials of a task, drawn from those run, all succeed. */
export interface PassK {
  k: number;
  rate: number;
}

const round = (v: number) => Math.round(v * 10_000) / 10_000;

/** C(c, k) / C(n, k): the chance that k of n trials, c of them successes, drawn without replacement, all succeed. */
function allOfK(c: number, n: number, k: number): number {
  let p = 1;
  for (let i = 0; i < k; i += 1) p *= (c - i) / (n - i);
  return Math.max(0, p);
}

/**
 * pass^k for k = 1 to n (n: the fewest trials of any task), the unbiased estimator of tau-bench:
 * per task C(c, k) / C(n, k) with c successes of its n trials, averaged over the tasks. pass^1 is
 * the mean success rate per task; pass^n is the share of tasks that succeeded on every trial.
 * How fast it falls with k says how reliable the agent is, which the rate alone does not. No
 * task: no entry.
 */
export function passHatK(tasks: readonly TaskCount[]): PassK[] {
  checkCounts(tasks, 'passHatK');
  if (tasks.length === 0) return [];
  const n = Math.min(...tasks.map((t) => t.trials));
  return Array.from({ length: n }, (_, i) => {
    const k = i + 1;
    const sum = tasks.reduce((s, t) => s + allOfK(t.successes, t.trials, k), 0);
    return { k, rate: round(sum / tasks.length) };
  });
}
