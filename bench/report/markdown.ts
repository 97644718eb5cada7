import type { Figure } from './figures.js';

function formatValue(value: number, unit: string): string {
  const abs = Math.abs(value);
  const digits = abs >= 100 ? 0 : abs >= 10 ? 1 : abs >= 1 ? 2 : 3;
  return `${value.toLocaleString('en-US', { maximumFractionDigits: digits })} ${unit}`;
}

/**
 * The ratio column: ours / alternative, with an arrow saying which way is better, so that
 * "2.1x" reads the same for a latency and a throughput.
 */
function formatRatio(figure: Figure): string {
  const alt = figure.alternative;
  if (alt === undefined || alt.value === 0) return '';
  const ratio = figure.value / alt.value;
  const better = figure.better === 'higher' ? ratio >= 1 : ratio <= 1;
  return `${ratio.toFixed(2)}x ${figure.better === 'higher' ? '(higher is better)' : '(lower is better)'}${better ? '' : ' ⚠'}`;
}

const cell = (text: string) => text.replaceAll('|', '\\|').replaceAll('\n', ' ');

/** One markdown table of every figure, grouped by benchmark in the order given. */
export function figuresTable(figures: readonly Figure[]): string {
  const lines = [
    '| benchmark | figure | ours | alternative | its figure | ours / alternative | goal | note |',
    '|---|---|---:|---|---:|---|---|---|',
  ];
  for (const f of figures) {
    lines.push(
      `| ${[
        f.bench,
        f.name,
        formatValue(f.value, f.unit),
        f.alternative?.name ?? '',
        f.alternative === undefined ? '' : formatValue(f.alternative.value, f.unit),
        formatRatio(f),
        f.goal ?? '',
        f.note ?? '',
      ]
        .map(cell)
        .join(' | ')} |`,
    );
  }
  return lines.join('\n');
}
