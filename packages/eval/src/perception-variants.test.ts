import { describe, expect, it } from 'vitest';
import type { EvalAgent } from './agent.js';
import { claimerAgent } from './agents/baselines.js';
import { oracleAgent } from './agents/oracle.js';
import { builtinTasks } from './builtin-tasks.js';
import { judge, trueAnswer } from './checks.js';
import { runEval } from './run-eval.js';
import type { Task } from './task-schema.js';
import type { TrialLog } from './trial-executor.js';
import { realiseTask } from './variant.js';

const perception = builtinTasks(['perception']);

/** The true answers of a task over seeds 1..n. */
function answersOver(task: Task, n: number): string[] {
  const check = task.checks.find((c) => c.kind === 'answer');
  if (check?.kind !== 'answer') throw new Error(`${task.id} asks nothing`);
  return Array.from({ length: n }, (_, i) => trueAnswer(realiseTask(task, i + 1), check.question));
}

/**
 * A cheat: it has learned each task's most common true answer (over seeds 1-200) and says it,
 * keyed by the instruction, without a single tool call.
 */
function lookupAgent(): EvalAgent {
  const table = new Map<string, string>();
  for (const task of perception) {
    const counts = new Map<string, number>();
    for (const a of answersOver(task, 200)) counts.set(a, (counts.get(a) ?? 0) + 1);
    const best = [...counts.entries()].sort((a, b) => b[1] - a[1])[0]?.[0] ?? '';
    table.set(task.instruction, best);
  }
  return {
    name: 'lookup',
    run: async (trial) => Promise.resolve({ answer: table.get(trial.instruction) ?? '' }),
  };
}

describe('perception variants', () => {
  it('change the true answer from seed to seed on every perception task', () => {
    for (const task of perception) {
      const seen = new Set(answersOver(task, 60));
      const least = task.id.includes('colour') ? 5 : task.id.includes('count') ? 4 : 2;
      expect(seen.size, task.id).toBeGreaterThanOrEqual(least);
    }
  });

  it('judge the answer against the world the seed realised', () => {
    const task = perception.find((t) => t.id === 'perception/colour-ahead-room') as Task;
    const end = (seed: number, answer: string) => ({
      variant: realiseTask(task, seed),
      log: { positions: [], safetyEvents: [] } as unknown as TrialLog,
      pose: realiseTask(task, seed).start,
      collisions: 0,
      estopLatched: false,
      answer,
    });
    const check = { kind: 'answer', question: 'colour-ahead' } as const;
    for (let seed = 1; seed <= 12; seed += 1) {
      const colour = realiseTask(task, seed).objects[0]?.colour ?? '';
      expect(judge(check, end(seed, `The box ahead is ${colour}.`)).passed).toBe(true);
      const other = colour === 'red' ? 'blue' : 'red';
      expect(judge(check, end(seed, `It's ${other}.`)).passed).toBe(false);
    }
  });

  it('leave a lookup table of the most common answers near chance, without a tool call', async () => {
    const report = await runEval({
      tasks: perception,
      agents: [lookupAgent()],
      trials: 20,
      seed: 1,
    });
    const lookup = report.scores.agents[0];
    expect(lookup?.trials.every((t) => t.toolCalls === 0)).toBe(true);
    // chance with the best guess: 1/6, 1/6, 3/8 (a count of 1-5), 1/2, 1/2: about 34 %
    expect(lookup?.overall.rate).toBeLessThan(0.5);
    for (const task of lookup?.tasks ?? []) expect(task.success.rate, task.task).toBeLessThan(0.75);
  }, 60_000);

  it('the oracle answers every seed right and the claimer none', async () => {
    const report = await runEval({
      tasks: perception,
      agents: [oracleAgent(), claimerAgent()],
      trials: 8,
      seed: 11,
      concurrency: 2,
    });
    const [oracle, claimer] = report.scores.agents;
    const failed = oracle?.trials.filter((t) => !t.success) ?? [];
    expect(failed.map((t) => `${t.task} seed ${t.seed}: ${t.failures.join('; ')}`)).toEqual([]);
    expect(oracle?.trials).toHaveLength(perception.length * 8);
    expect(claimer?.overall.successes).toBe(0);
  }, 60_000);
});
