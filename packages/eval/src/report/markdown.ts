import type { EvalReport } from '../run-eval.js';
import { summaryTable } from './table.js';

const pct = (rate: number) => `${Math.round(rate * 100)} %`;
const num = (v: number | null, digits = 3) =>
  v === null ? '-' : String(Math.round(v * 10 ** digits) / 10 ** digits);

/**
 * The report in Markdown: the summary by group, the plot (`plotFile`, when written beside it),
 * then each agent's tasks: success over k with the 95 % Wilson interval, pass^k, collisions,
 * mean final position error, path length over the planner's optimum, calls and refusals.
 */
export function markdownReport(report: EvalReport, options: { plotFile?: string } = {}): string {
  const { scores } = report;
  const lines = [
    '# hal eval',
    '',
    `Seed ${scores.seed}, ${scores.trialsPerTask} trial(s) per task, ${scores.tasks.length} task(s). ` +
      'Success is computed from the simulator’s ground truth' +
      (scores.agents.some((a) => a.on !== 'simulator')
        ? '; on a robot (the rows AGENT@ROBOT), from what the robot itself reports (its odometry).'
        : '.'),
    '',
    '```text',
    summaryTable(report),
    '```',
    '',
  ];
  if (options.plotFile !== undefined) lines.push(`![Success by group](${options.plotFile})`, '');
  for (const agent of scores.agents) {
    lines.push(
      `## ${agent.agent}`,
      '',
      agent.on === 'simulator'
        ? 'In the simulator, scored from its ground truth.'
        : `On ${agent.on}, scored from what the robot reports.`,
      '',
      ...(agent.modelFailure === null
        ? []
        : [
            `**The model could not be used** in ${agent.modelFailure.trials} trial(s)` +
              (agent.modelFailure.notRun > 0
                ? ` (then ${agent.modelFailure.notRun} more were not run)`
                : '') +
              `: ${agent.modelFailure.code}: ${agent.modelFailure.message}. Those trials are not scored.`,
            '',
          ]),
      '| task | success | 95 % CI | pass^k | collisions | position error (m) | path / optimum | calls | refused |',
      '|---|---|---|---|---|---|---|---|---|',
    );
    for (const t of agent.tasks) {
      lines.push(
        `| ${t.task} | ${t.success.successes}/${t.success.trials} | ${pct(t.success.low)}–${pct(t.success.high)} | ${t.passAll ? 'yes' : 'no'} | ${t.collisions} | ${num(t.meanPositionErrorM)} | ${num(t.meanPathRatio, 2)} | ${t.toolCalls} | ${t.refusedCalls} |`,
      );
    }
    const failures = agent.trials.filter((t) => !t.success && t.modelFailure === null).slice(0, 20);
    if (failures.length > 0) {
      lines.push('', 'Failures (first 20):', '');
      for (const f of failures) lines.push(`- ${f.task} seed ${f.seed}: ${f.failures.join('; ')}`);
    }
    lines.push('');
  }
  return lines.join('\n');
}
