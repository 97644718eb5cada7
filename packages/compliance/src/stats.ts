import type { Measured } from './report.js';

/** p50, p99 and max of `values` (nearest rank); zeros for no values. */
export function summarize(values: readonly number[]): Measured {
  if (values.length === 0) return { samples: 0, p50Ms: 0, p99Ms: 0, maxMs: 0 };
  const sorted = [...values].sort((a, b) => a - b);
  const rank = (p: number) => sorted[Math.min(sorted.length - 1, Math.ceil(p * sorted.length) - 1)];
  return {
    samples: sorted.length,
    p50Ms: rank(0.5) ?? 0,
    p99Ms: rank(0.99) ?? 0,
    maxMs: sorted[sorted.length - 1] ?? 0,
  };
}
