import { describe, expect, it } from 'vitest';
import { claimerAgent, naiveAgent } from '../agents/baselines.js';
import { oracleAgent } from '../agents/oracle.js';
import { builtinTasks } from '../builtin-tasks.js';
import { runEval } from '../run-eval.js';
import { markdownReport } from './markdown.js';
import { successSvg } from './svg.js';
import { summaryTable } from './table.js';

describe('the reports', async () => {
  const report = await runEval({
    tasks: builtinTasks(['precision', 'robustness']),
    agents: [oracleAgent(), naiveAgent(), claimerAgent()],
    trials: 2,
    seed: 3,
  });

  it('tabulate each agent by group with its overall rate and interval', () => {
    const lines = summaryTable(report).split('\n');
    expect(lines[0]).toMatch(
      /^agent\s+precision\s+robustness\s+overall\s+95% CI\s+calls\s+refused\s+tokens$/,
    );
    expect(lines[1]).toMatch(/^oracle\s+100% 12\/12\s+100% 8\/8\s+100%\s+/);
    expect(lines[3]).toMatch(/^claimer\s+0% 0\/12\s+0% 0\/8\s+0%\s+0%-16%\s+0\s+0\s+0$/);
  });

  it('write Markdown with a row per task and the failures named', () => {
    const md = markdownReport(report, { plotFile: 'eval.svg' });
    expect(md).toContain('![Success by group](eval.svg)');
    expect(md).toContain('| precision/drive-30cm | 2/2 |');
    expect(md).toMatch(/- robustness\/move-fails seed 3: displacement: /);
  });

  it('plot one bar per agent and group, and the same bytes for the same report', () => {
    const svg = successSvg(report);
    expect(svg.match(/<rect [^>]*><title>/g)).toHaveLength(3 * 3);
    expect(svg).toContain('<title>naive precision: ');
    expect(successSvg(report)).toBe(svg);
  });
});
