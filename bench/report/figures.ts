// What a benchmark reports, as one line of JSON each on its standard output (after a
// `BENCH_JSON ` prefix), so that `pnpm bench` can gather every figure into one report. A benchmark
// still prints its own human-readable lines; these records are the machine-readable copy.
import { z } from 'zod';

export const BENCH_JSON_PREFIX = 'BENCH_JSON ';

/** One measured figure, beside the alternative it was measured against in the same run. */
export const FigureSchema = z.object({
  kind: z.literal('figure'),
  /** The benchmark file's short name, e.g. `physical`. */
  bench: z.string().min(1),
  /** What was measured, e.g. `UDP round trip p99`. */
  name: z.string().min(1),
  value: z.number().finite(),
  unit: z.string().min(1),
  /** Whether a larger value is better (throughput) or a smaller one (latency). */
  better: z.enum(['higher', 'lower']),
  /** The alternative, run in the same process or run, interleaved. */
  alternative: z.object({ name: z.string().min(1), value: z.number().finite() }).optional(),
  /** The goal this figure is held to, in words, e.g. `<= 1.3x raw`. */
  goal: z.string().optional(),
  /** Whether this run met the goal, where the benchmark can tell (a goal in words may not say). */
  met: z.boolean().optional(),
  /** Anything a reader must know to read the figure honestly. */
  note: z.string().optional(),
});
export type Figure = z.infer<typeof FigureSchema>;

/** One point of a plot of how a cost grows with the work (series by name). */
export const PointSchema = z.object({
  kind: z.literal('point'),
  plot: z.string().regex(/^[a-z0-9-]+$/),
  title: z.string().min(1),
  series: z.string().min(1),
  x: z.number().finite(),
  y: z.number().finite(),
  xLabel: z.string().min(1),
  yLabel: z.string().min(1),
  logX: z.boolean().optional(),
  logY: z.boolean().optional(),
});
export type Point = z.infer<typeof PointSchema>;

export const RecordSchema = z.discriminatedUnion('kind', [FigureSchema, PointSchema]);
export type BenchRecord = z.infer<typeof RecordSchema>;

function emit(record: BenchRecord): void {
  console.log(BENCH_JSON_PREFIX + JSON.stringify(RecordSchema.parse(record)));
}

/** Reports a figure (and prints nothing else). */
export function reportFigure(figure: Omit<Figure, 'kind'>): void {
  emit({ kind: 'figure', ...figure });
}

/** Reports one point of a plot. */
export function reportPoint(point: Omit<Point, 'kind'>): void {
  emit({ kind: 'point', ...point });
}

/** The value at percentile `p` (0..100) of `samples`, nearest rank. */
export function percentile(samples: readonly number[], p: number): number {
  const sorted = [...samples].sort((a, b) => a - b);
  return (
    sorted[Math.min(sorted.length - 1, Math.max(0, Math.ceil((p / 100) * sorted.length) - 1))] ?? 0
  );
}
