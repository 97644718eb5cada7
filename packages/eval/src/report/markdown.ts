import type { EvalReport } from '../run-eval.js';
import { summaryTable } from './table.js';

const pct = (rate: number) => `${Math.round(rate * 100)} %`;
const num = (v: number | null, digits = 3) =>
  v === null ? '-' : String(Math.round(v * 10 ** digits) / 10 ** digits);

/** pass^k of every agent for k = 1 to the trials per task, one row per agent. */
function passKTable(report: EvalReport): string[] {
  const ks = Array.from({ length: report.scores.trialsPerTask }, (_, i) => i + 1);
  return [
    `| agent | ${ks.map((k) => `pass^${k}`).join(' | ')} |`,
    `|---|${ks.map(() => '---|').join('')}`,
    ...report.scores.agents.map(
      (a) =>
        `| ${a.agent} | ${ks
          .map((k) => a.passK.find((p) => p.k === k))
          .map((p) => (p === undefined ? '-' : pct(p.rate)))
          .join(' | ')} |`,
    ),
  ];
}

/** Each agent's rate by group and overall with the interval over tasks, one row each. */
function groupTable(report: EvalReport): string[] {
  const rows = report.scores.agents.flatMap((a) =>
    [
      ...a.groups.map((g) => ({ name: g.group as string, s: g.success })),
      { name: 'overall', s: a.overall },
    ]
      .filter((r) => r.s.trials > 0)
      .map(
        ({ name, s }) =>
          `| ${a.agent} | ${name} | ${s.successes}/${s.trials} | ${pct(s.low)}–${pct(s.high)} | ${s.tasks} |`,
      ),
  );
  return [
    '| agent | group | success | 95 % CI (over tasks) | tasks |',
    '|---|---|---|---|---|',
    ...rows,
  ];
}

/**
 * The report in Markdown: the summary by group (the overall interval a bootstrap over tasks),
 * pass^k of each agent, each agent's rates by group with their intervals over tasks, the plot (`plotFile`, when written beside it), then each agent's tasks:
 * success over k with the task's 95 % Wilson interval, whether all k passed, collisions, mean
 * final position error, path length over the planner's optimum, calls and refusals. An agent
 * given the ground truth is marked an oracle.
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
    'The 95 % interval of a rate over tasks is a bootstrap over the tasks (the seeds of one task ' +
      'are not independent trials). pass^k is the chance that k trials of a task all succeed, ' +
      'averaged over the tasks (C(c, k) / C(n, k) per task, c successes of n trials):',
    '',
    ...passKTable(report),
    '',
    ...groupTable(report),
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
      ...(agent.usesGroundTruth
        ? [
            '**An oracle: it reads the ground truth** (the task and the world as the seed placed ' +
              'them, and the true pose), so it is a reference, not an agent under test.',
            '',
          ]
        : []),
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
      '| task | success | 95 % CI (Wilson) | all k passed | collisions | position error (m) | path / optimum | calls | refused |',
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
