import { CHECK_GROUPS } from './report.js';
import type { CheckResult, ComplianceReport } from './report.js';

const ms = (value: number) => (value < 10 ? value.toFixed(2) : value.toFixed(0));

/** The measured column: latencies, or a stream's rate. */
export function measuredText(check: CheckResult): string {
  const m = check.measured;
  if (check.rateHz !== undefined) {
    const rate = `${check.rateHz.toFixed(1)} Hz`;
    return m === undefined ? rate : `${rate} (interval p99 ${ms(m.p99Ms)} ms)`;
  }
  if (m === undefined || m.samples === 0) return '';
  return `p50 ${ms(m.p50Ms)} p99 ${ms(m.p99Ms)} max ${ms(m.maxMs)} ms (n=${m.samples})`;
}

/** The spec column: the latency class, or the stream rate band. */
export function specText(check: CheckResult, judge: ComplianceReport['judge']): string {
  if (check.latencyClass !== undefined) {
    return `${check.latencyClass.name} < ${check.latencyClass.limitMs} ms (${judge})`;
  }
  if (check.group === 'timing' && check.rateHz !== undefined) return '10-100 Hz';
  return '';
}

const pad = (text: string, width: number) => text + ' '.repeat(Math.max(0, width - text.length));

/** The report as a table for people: one row per check, reasons under failures and skips. */
export function formatReport(report: ComplianceReport): string {
  const header = ['RESULT', 'CAPABILITY', 'GROUP', 'CHECK', 'MEASURED', 'SPEC'];
  const rows = report.checks.map((c) => [
    c.status.toUpperCase(),
    c.capability,
    c.group,
    c.title,
    measuredText(c),
    specText(c, report.judge),
  ]);
  const widths = header.map((h, i) => Math.max(h.length, ...rows.map((r) => (r[i] ?? '').length)));
  const line = (cells: string[]) =>
    cells
      .map((cell, i) => pad(cell, widths[i] ?? 0))
      .join('  ')
      .trimEnd();
  const lines = [
    `device ${report.deviceId} (${report.deviceType}, ${report.mode})${report.addressed === undefined ? ', the default device' : ''}`,
    `announces ${report.caps.join(', ') || 'nothing'}`,
    '',
    line(header),
  ];
  report.checks.forEach((check, i) => {
    lines.push(line(rows[i] ?? []));
    if (check.status !== 'pass') lines.push(`        ${check.reason}`);
  });
  const { passed, failed, skipped } = report.summary;
  // A run of some groups says which were left out: it is not a verdict on those.
  const left = CHECK_GROUPS.filter((g) => !report.groups.includes(g));
  const scope = left.length === 0 ? '' : ` (${left.join(', ')} not checked)`;
  lines.push(
    '',
    `${passed} passed, ${failed} failed, ${skipped} skipped in ${(report.durationMs / 1000).toFixed(1)} s: ${report.ok ? 'COMPLIANT' : 'NOT COMPLIANT'}${scope}`,
  );
  return `${lines.join('\n')}\n`;
}
