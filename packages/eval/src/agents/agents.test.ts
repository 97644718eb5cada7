import { describe, expect, it } from 'vitest';
import { builtinTasks } from '../builtin-tasks.js';
import { runEval } from '../run-eval.js';
import { claimerAgent, naiveAgent } from './baselines.js';
import { oracleAgent } from './oracle.js';

describe('the oracle', () => {
  it('succeeds on every built-in task for every one of five seeds', async () => {
    const report = await runEval({
      tasks: builtinTasks(),
      agents: [oracleAgent()],
      trials: 5,
      seed: 1,
      concurrency: 2,
    });
    const failed = report.scores.agents[0]?.trials.filter((t) => !t.success) ?? [];
    expect(failed.map((t) => `${t.task} seed ${t.seed}: ${t.failures.join('; ')}`)).toEqual([]);
    expect(report.scores.agents[0]?.trials).toHaveLength(builtinTasks().length * 5);
  }, 60_000);

  it('gives byte-identical scores in two runs with the same seed, whatever the concurrency', async () => {
    const run = (concurrency: number) =>
      runEval({ tasks: builtinTasks(), agents: [oracleAgent()], trials: 2, seed: 7, concurrency });
    const [a, b] = await Promise.all([run(1), run(4)]);
    expect(JSON.stringify(b.scores)).toBe(JSON.stringify(a.scores));
    const other = await runEval({
      tasks: builtinTasks(['precision']),
      agents: [oracleAgent()],
      trials: 1,
      seed: 8,
    });
    const same = a.scores.agents[0]?.trials.find(
      (t) => t.task === 'precision/drive-30cm' && t.seed === 8,
    );
    expect(same).toEqual(other.scores.agents[0]?.trials[0]);
  }, 60_000);
});

describe('the baselines', () => {
  it('the naive agent fails most tasks, and a claim without moving scores 0 on every task', async () => {
    const report = await runEval({
      tasks: builtinTasks(),
      agents: [naiveAgent(), claimerAgent()],
      trials: 2,
      seed: 1,
    });
    const [naive, claimer] = report.scores.agents;
    expect(naive?.overall.rate).toBeLessThan(0.5);
    expect(naive?.overall.successes).toBeGreaterThan(0);
    expect(claimer?.overall.successes).toBe(0);
    expect(claimer?.tasks.every((t) => t.success.successes === 0)).toBe(true);
    expect(claimer?.trials.every((t) => t.toolCalls === 0 && t.pathLengthM === 0)).toBe(true);
  }, 60_000);
});
