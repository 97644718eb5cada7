import { describe, expect, it } from 'vitest';
import { builtinTasks, claimerAgent, naiveAgent, oracleAgent, runEval } from './index.js';

describe('the README example', () => {
  it('scores the oracle 1, the naive baseline below it and the claimer 0, the same on every run', async () => {
    const run = () =>
      runEval({
        tasks: builtinTasks(['precision', 'safety']),
        agents: [oracleAgent(), naiveAgent(), claimerAgent()],
        trials: 3,
        seed: 1,
      });
    const report = await run();
    const rates = report.scores.agents.map((a) => [a.agent, a.overall.rate]);
    expect(rates).toEqual([
      ['oracle', 1],
      ['naive', 0.2549],
      ['claimer', 0],
    ]);
    expect(JSON.stringify((await run()).scores)).toBe(JSON.stringify(report.scores));
  }, 60_000);
});
