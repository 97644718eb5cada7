import { describe, expect, it } from 'vitest';
import { claimerAgent, naiveAgent } from '../agents/baselines.js';
import { oracleAgent } from '../agents/oracle.js';
import { builtinTasks } from '../builtin-tasks.js';
import { runEval } from '../run-eval.js';
import { markdownReport } from './markdown.js';
import { successSvg } from './svg.js';
import { summaryTable, tableKs } from './table.js';

/** Ten tasks of two groups (a fixed set: the built-in groups grow). */
const TASKS = [
  'precision/drive-30cm',
  'precision/back-20cm',
  'precision/turn-left-90',
  'precision/turn-right-45',
  'precision/come-back',
  'precision/corner',
  'robustness/move-fails',
  'robustness/timeout',
  'robustness/leash-distance',
  'robustness/rotate-fails',
];

describe('the reports', async () => {
  const report = await runEval({
    tasks: builtinTasks(['precision', 'robustness']).filter((t) => TASKS.includes(t.id)),
    agents: [oracleAgent(), naiveAgent(), claimerAgent()],
    trials: 2,
    seed: 3,
  });

  it('tabulate each agent by group with its overall rate, interval over tasks and pass^k', () => {
    const lines = summaryTable(report).split('\n');
    expect(lines[0]).toMatch(
      /^agent\s+precision\s+robustness\s+overall\s+95% CI\s+pass\^1\.\.2\s+calls\s+refused\s+tokens\s+truth$/,
    );
    expect(lines[1]).toMatch(
      /^oracle\s+100% 12\/12\s+100% 8\/8\s+100%\s+\d+%-100%\s+100% 100%\s+\d+\s+0\s+0\s+oracle \(reads the ground truth\)$/,
    );
    // 10 tasks, none passed: Wilson over the 10 tasks, not over the 20 trials (0%-16%)
    expect(lines[3]).toMatch(/^claimer\s+0% 0\/12\s+0% 0\/8\s+0%\s+0%-28%\s+0% 0%\s+0\s+0\s+0$/);
  });

  it('mark the oracle, and give pass^k and the interval over tasks in the JSON', () => {
    expect(report.version).toBe(3);
    const [oracle, naive, claimer] = report.scores.agents;
    expect([oracle, naive, claimer].map((a) => a?.usesGroundTruth)).toEqual([true, false, false]);
    expect(oracle?.passK).toEqual([
      { k: 1, rate: 1 },
      { k: 2, rate: 1 },
    ]);
    expect(naive?.overall).toMatchObject({ tasks: 10, interval: 'bootstrap-tasks' });
    expect(naive?.overall.rate).toBe(naive?.passK[0]?.rate);
    expect(naive?.groups[0]?.success).toMatchObject({ tasks: 6, interval: expect.any(String) });
    expect(claimer?.overall).toMatchObject({ interval: 'wilson-tasks', low: 0, high: 0.2775 });
  });

  it('show at most five k in the table, the last of them n', () => {
    expect(tableKs(1)).toEqual([1]);
    expect(tableKs(5)).toEqual([1, 2, 3, 4, 5]);
    expect(tableKs(20)).toEqual([1, 2, 3, 4, 20]);
  });

  it('write Markdown with a row per task and the failures named', () => {
    const md = markdownReport(report, { plotFile: 'eval.svg' });
    expect(md).toContain('![Success by group](eval.svg)');
    expect(md).toContain('| precision/drive-30cm | 2/2 |');
    expect(md).toMatch(/- robustness\/move-fails seed 3: displacement: /);
    expect(md).toContain('| agent | pass^1 | pass^2 |');
    expect(md).toContain('| claimer | 0 % | 0 % |');
    expect(md).toContain('| claimer | robustness | 0/8 | 0 %–49 % | 4 |');
    expect(md).toMatch(/\| naive \| overall \| 6\/20 \| \d+ %–\d+ % \| 10 \|/);
    expect(md.match(/An oracle: it reads the ground truth/g)).toHaveLength(1);
    expect(md.indexOf('An oracle')).toBeGreaterThan(md.indexOf('## oracle'));
    expect(md.indexOf('An oracle')).toBeLessThan(md.indexOf('## naive'));
  });

  it('plot one bar per agent and group, and the same bytes for the same report', () => {
    const svg = successSvg(report);
    expect(svg.match(/<rect [^>]*><title>/g)).toHaveLength(3 * 3);
    expect(svg).toContain('<title>naive precision: ');
    expect(svg).toContain('>oracle (oracle: reads the ground truth)</text>');
    expect(successSvg(report)).toBe(svg);
  });
});
