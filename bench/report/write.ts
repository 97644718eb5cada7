import { mkdir, readdir, rm, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import type { BenchRecord, Figure, Point } from './figures.js';
import { describeMachine } from './machine.js';
import { figuresTable } from './markdown.js';
import { plotSvg } from './plot.js';

/** What one benchmark program gave. */
export interface BenchRun {
  /** The file's short name (`physical` for physical.bench.ts). */
  bench: string;
  ok: boolean;
  records: BenchRecord[];
  malformed: string[];
  seconds: number;
}

/** Writes `README.md` and one SVG per plot into `dir` (replacing the previous report). */
export async function writeReport(dir: string, runs: readonly BenchRun[]): Promise<string> {
  await mkdir(dir, { recursive: true });
  for (const name of await readdir(dir)) {
    if (name.endsWith('.svg')) await rm(join(dir, name));
  }
  const figures: Figure[] = [];
  const plots = new Map<string, Point[]>();
  for (const run of runs) {
    for (const record of run.records) {
      if (record.kind === 'figure') figures.push(record);
      else plots.set(record.plot, [...(plots.get(record.plot) ?? []), record]);
    }
  }
  const images: string[] = [];
  for (const [id, points] of plots) {
    await writeFile(join(dir, `${id}.svg`), await plotSvg(points));
    images.push(`### ${points[0]?.title ?? id}\n\n![${id}](${id}.svg)`);
  }
  const failed = runs.filter((run) => !run.ok || run.malformed.length > 0);
  const text = [
    '# Benchmark report',
    '',
    `Written by \`pnpm bench\` on ${new Date().toISOString().slice(0, 10)}.`,
    '',
    `Machine: ${describeMachine()}.`,
    '',
    'Every figure here was measured in this run. Each alternative ran in the same run, interleaved',
    'with ours where the benchmark says so; a figure quoted from elsewhere says so in its note.',
    '',
    '## Figures',
    '',
    figuresTable(figures),
    '',
    '## How cost grows with the work',
    '',
    ...images.flatMap((image) => [image, '']),
    '## Runs',
    '',
    '| benchmark | result | wall time |',
    '|---|---|---:|',
    ...runs.map(
      (run) =>
        `| ${run.bench} | ${run.ok ? 'ok' : 'FAILED'}${run.malformed.length > 0 ? `, ${run.malformed.length} malformed record(s)` : ''} | ${run.seconds.toFixed(0)} s |`,
    ),
    '',
  ].join('\n');
  await writeFile(join(dir, 'README.md'), text);
  return failed.length === 0 ? 'ok' : `${failed.length} benchmark(s) failed`;
}
