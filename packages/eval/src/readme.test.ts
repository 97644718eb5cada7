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
    const [oracle, naive, claimer] = report.scores.agents;
    expect(oracle?.overall.rate).toBe(1);
    expect(naive?.overall.rate).toBeLessThan(0.5);
    expect(claimer?.overall.rate).toBe(0);
    expect(JSON.stringify((await run()).scores)).toBe(JSON.stringify(report.scores));
  }, 60_000);
});
