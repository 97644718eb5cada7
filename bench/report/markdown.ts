import type { Figure } from './figures.js';

function formatValue(value: number, unit: string): string {
  const abs = Math.abs(value);
  const digits = abs >= 100 ? 0 : abs >= 10 ? 1 : abs >= 1 ? 2 : 3;
  return `${value.toLocaleString('en-US', { maximumFractionDigits: digits })} ${unit}`;
}

/**
 * A ratio with enough digits to be read: two decimals from 0.1 up, two significant digits below
 * (0.0013x, not 0.00x).
 */
export function formatRatioNumber(ratio: number): string {
  if (ratio === 0 || Math.abs(ratio) >= 0.1) return `${ratio.toFixed(2)}x`;
  return `${Number(ratio.toPrecision(2)).toString()}x`;
}

/**
 * The ratio column: ours / alternative, with an arrow saying which way is better, so that
 * "2.1x" reads the same for a latency and a throughput; a lead of 10x or more is also said in
 * words ("787x better"), as a tiny ratio is hard to read.
 */
function formatRatio(figure: Figure): string {
  const alt = figure.alternative;
  if (alt === undefined || alt.value === 0) return '';
  const ratio = figure.value / alt.value;
  const better = figure.better === 'higher' ? ratio >= 1 : ratio <= 1;
  const lead = figure.better === 'higher' ? ratio : 1 / ratio;
  const way = figure.better === 'higher' ? 'higher is better' : 'lower is better';
  const words =
    lead >= 10 && Number.isFinite(lead)
      ? `; ${Math.round(lead).toLocaleString('en-US')}x better`
      : '';
  return `${formatRatioNumber(ratio)} (${way}${words})${better ? '' : ' ⚠'}`;
}

/** The goal, and whether this run met it when the benchmark could tell. */
function formatGoal(figure: Figure): string {
  if (figure.goal === undefined) return '';
  if (figure.met === undefined) return figure.goal;
  return `${figure.goal}: ${figure.met ? 'met' : 'NOT met'}`;
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
        formatGoal(f),
        f.note ?? '',
      ]
        .map(cell)
        .join(' | ')} |`,
    );
  }
  return lines.join('\n');
}
