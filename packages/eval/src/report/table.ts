import type { PassK } from '../pass-k.js';
import type { AgentModelFailure, EvalReport } from '../run-eval.js';

const pct = (rate: number) => `${Math.round(rate * 100)}%`;

/** The groups of a report, in the order they first appear. */
export function reportGroups(report: EvalReport): string[] {
  return [...new Set(report.scores.agents.flatMap((a) => a.groups.map((g) => g.group)))];
}

/** Pads the cells of rows into aligned columns. */
export function alignColumns(rows: readonly (readonly string[])[]): string {
  const widths: number[] = [];
  for (const row of rows)
    row.forEach((cell, i) => (widths[i] = Math.max(widths[i] ?? 0, cell.length)));
  return rows
    .map((row) =>
      row
        .map((cell, i) => cell.padEnd(widths[i] ?? 0))
        .join('  ')
        .trimEnd(),
    )
    .join('\n');
}

/** What the table says of an agent whose model failed: in how many trials, how many not run. */
export function modelFailureNote(failure: AgentModelFailure): string {
  const trials = `${failure.trials} trial${failure.trials === 1 ? '' : 's'}`;
  return `model failed (${failure.code}) in ${trials}${failure.notRun > 0 ? `, ${failure.notRun} not run` : ''}`;
}

/** What the table says of an agent given the ground truth. */
export const ORACLE_NOTE = 'oracle (reads the ground truth)';

/** The k of pass^k the table shows for n trials per task: all up to 5, else 1 to 4 and n. */
export function tableKs(n: number): number[] {
  const ks = Array.from({ length: Math.min(n, 5) }, (_, i) => i + 1);
  if (n > 5) ks[4] = n;
  return ks;
}

/** pass^k at each of `ks`, in percent, side by side. */
function passKCell(passK: readonly PassK[], ks: readonly number[]): string {
  return ks
    .map((k) => passK.find((p) => p.k === k))
    .map((p) => (p === undefined ? '-' : pct(p.rate)))
    .join(' ');
}

/**
 * One line per agent: its success rate by group (successes/trials) and overall with the 95 %
 * interval (a bootstrap over tasks), pass^k, tool calls, refused calls and tokens; the rates count
 * only scored trials. An agent given the ground truth is marked an oracle. An agent whose model
 * failed (never answered) has a last column that says so; with no scored trial its rates are `-`,
 * never 0 %.
 */
export function summaryTable(report: EvalReport): string {
  const groups = reportGroups(report);
  const anyFailure = report.scores.agents.some((a) => a.modelFailure !== null);
  const anyOracle = report.scores.agents.some((a) => a.usesGroundTruth);
  const ks = tableKs(report.scores.trialsPerTask);
  const head = [
    'agent',
    ...groups,
    'overall',
    '95% CI',
    ks.length === report.scores.trialsPerTask && ks.length > 1
      ? `pass^1..${ks.length}`
      : `pass^${ks.join(',')}`,
    'calls',
    'refused',
    'tokens',
    ...(anyOracle ? ['truth'] : []),
    ...(anyFailure ? ['model'] : []),
  ];
  const rows = report.scores.agents.map((a) => {
    const none = a.overall.trials === 0;
    const byGroup = new Map(a.groups.map((g) => [g.group as string, g]));
    const calls = a.trials.reduce((s, t) => s + t.toolCalls, 0);
    const refused = a.trials.reduce((s, t) => s + t.refusedCalls, 0);
    const tokens = a.trials.reduce((s, t) => s + t.tokensIn + t.tokensOut, 0);
    return [
      a.agent,
      ...groups.map((g) => {
        const s = byGroup.get(g)?.success;
        return s === undefined ? '-' : `${pct(s.rate)} ${s.successes}/${s.trials}`;
      }),
      none ? '-' : pct(a.overall.rate),
      none ? '-' : `${pct(a.overall.low)}-${pct(a.overall.high)}`,
      none ? '-' : passKCell(a.passK, ks),
      String(calls),
      String(refused),
      String(tokens),
      ...(anyOracle ? [a.usesGroundTruth ? ORACLE_NOTE : ''] : []),
      ...(anyFailure ? [a.modelFailure === null ? 'ok' : modelFailureNote(a.modelFailure)] : []),
    ];
  });
  return alignColumns([head, ...rows]);
}
