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

/**
 * One line per agent: its success rate by group (successes/trials) and overall with the 95 %
 * interval, tool calls, refused calls and tokens; the rates count only scored trials. An agent
 * whose model failed (never answered) has a last column that says so; with no scored trial its
 * rates are `-`, never 0 %.
 */
export function summaryTable(report: EvalReport): string {
  const groups = reportGroups(report);
  const anyFailure = report.scores.agents.some((a) => a.modelFailure !== null);
  const head = [
    'agent',
    ...groups,
    'overall',
    '95% CI',
    'calls',
    'refused',
    'tokens',
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
      String(calls),
      String(refused),
      String(tokens),
      ...(anyFailure ? [a.modelFailure === null ? 'ok' : modelFailureNote(a.modelFailure)] : []),
    ];
  });
  return alignColumns([head, ...rows]);
}
