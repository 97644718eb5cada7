// `hal eval --check-tasks`: the oracle (which reads the simulator's ground truth) runs every task
// over the seeds asked for; a trial it cannot pass is a task to fix, not a hard one, since any
// agent's 0 on it would be blamed on the agent.
import { oracleAgent, runEval } from '@hal/eval';
import type { Task, TrialScore } from '@hal/eval';

/** A task and seed the oracle could not solve, and the check that failed. */
export interface UnsolvedTrial {
  task: string;
  seed: number;
  why: string;
}

/** Options of {@link checkTasks}. */
export interface CheckTasksOptions {
  /** Seeds per task: seed, seed + 1, ... */
  trials: number;
  seed: number;
  concurrency: number;
  /** Called after each trial, e.g. for progress. */
  onTrial?: (score: TrialScore, done: number, total: number) => void;
}

/** Runs the oracle over every task and seed; answers those it could not solve, in run order. */
export async function checkTasks(
  tasks: readonly Task[],
  options: CheckTasksOptions,
): Promise<UnsolvedTrial[]> {
  const unsolved: UnsolvedTrial[] = [];
  await runEval({
    tasks,
    agents: [oracleAgent()],
    trials: options.trials,
    seed: options.seed,
    concurrency: options.concurrency,
    guard: false,
    onTrial: ({ score, done, total }) => {
      if (!score.success)
        unsolved.push({
          task: score.task,
          seed: score.seed,
          why: score.failures.join('; ') || 'failed',
        });
      options.onTrial?.(score, done, total);
    },
  });
  return unsolved.sort((a, b) => a.task.localeCompare(b.task) || a.seed - b.seed);
}

/** The lines `hal eval --check-tasks` prints: one per unsolved trial, then a summary. */
export function checkTasksText(
  unsolved: readonly UnsolvedTrial[],
  tasks: number,
  trials: number,
): string {
  const lines = unsolved.map((u) => `${u.task} seed ${u.seed}: the oracle failed: ${u.why}`);
  const bad = new Set(unsolved.map((u) => u.task)).size;
  lines.push(
    unsolved.length === 0
      ? `the oracle solved all ${tasks} task(s) on ${trials} seed(s) each`
      : `the oracle could not solve ${bad} of ${tasks} task(s) (${unsolved.length} of ${tasks * trials} trial(s))`,
  );
  return `${lines.join('\n')}\n`;
}
