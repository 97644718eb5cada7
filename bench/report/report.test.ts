import { mkdtemp, readFile, readdir, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { collectRecords } from './collect.js';
import { BENCH_JSON_PREFIX, percentile } from './figures.js';
import type { Figure } from './figures.js';
import { figuresTable, formatRatioNumber } from './markdown.js';
import { stolenMsFromProcStat } from './stolen-time.js';
import { writeReport } from './write.js';

const latency: Figure = {
  kind: 'figure',
  bench: 'physical',
  name: 'UDP round trip p99',
  value: 120,
  unit: 'us',
  better: 'lower',
  alternative: { name: 'raw dgram', value: 60 },
  goal: '<= 1.3x raw',
};

describe('collectRecords', () => {
  it('keeps the records, leaves the human lines, and reports lines that are not valid records', () => {
    const output = [
      'UDP round trip:',
      BENCH_JSON_PREFIX + JSON.stringify(latency),
      BENCH_JSON_PREFIX + '{"kind":"figure"', // cut short
      BENCH_JSON_PREFIX + JSON.stringify({ ...latency, value: 'fast' }),
      BENCH_JSON_PREFIX +
        JSON.stringify({
          kind: 'point',
          plot: 'rtt',
          title: 't',
          series: 'raw',
          x: 1,
          y: 2,
          xLabel: 'x',
          yLabel: 'y',
        }),
    ].join('\n');
    const { records, malformed } = collectRecords(output);
    expect(records.map((r) => r.kind)).toEqual(['figure', 'point']);
    expect(malformed).toHaveLength(2);
  });
});

describe('figuresTable', () => {
  it('gives ours / alternative and marks a figure that is worse than its alternative', () => {
    const table = figuresTable([
      latency,
      {
        ...latency,
        name: 'frames/s',
        unit: 'frames/s',
        better: 'higher',
        value: 300,
        alternative: { name: 'one-shot', value: 100 },
      },
    ]);
    expect(table).toContain(
      '| physical | UDP round trip p99 | 120 us | raw dgram | 60 us | 2.00x (lower is better) ⚠ |',
    );
    expect(table).toContain('| 3.00x (higher is better) |');
  });

  it('says beside the goal whether the run met it, where the benchmark could tell', () => {
    const table = figuresTable([
      { ...latency, met: false },
      { ...latency, name: 'UDP round trip p50', goal: '<= 1.1x raw', met: true },
      { ...latency, name: 'e-stop p99', goal: 'within one round trip' },
    ]);
    expect(table).toContain('| <= 1.3x raw: NOT met |');
    expect(table).toContain('| <= 1.1x raw: met |');
    expect(table).toContain('| within one round trip |');
  });

  it('prints a large lead with its digits and in words, never as 0.00x', () => {
    const table = figuresTable([
      {
        ...latency,
        name: 'e-stop p50',
        unit: 'ms',
        value: 1.27,
        alternative: { name: 'queued', value: 1000 },
      },
      {
        ...latency,
        name: 'throughput',
        unit: 'frames/s',
        better: 'higher',
        value: 787_000,
        alternative: { name: 'old', value: 1000 },
      },
    ]);
    expect(table).toContain('| 0.0013x (lower is better; 787x better) |');
    expect(table).toContain('| 787.00x (higher is better; 787x better) |');
    expect(table).not.toContain('0.00x');
  });
});

describe('formatRatioNumber', () => {
  it('keeps two decimals from 0.1 up and two significant digits below', () => {
    expect(formatRatioNumber(1.4449)).toBe('1.44x');
    expect(formatRatioNumber(0.25)).toBe('0.25x');
    expect(formatRatioNumber(0.0123)).toBe('0.012x');
    expect(formatRatioNumber(0.00012345)).toBe('0.00012x');
    expect(formatRatioNumber(0)).toBe('0.00x');
  });
});

describe('percentile', () => {
  it('takes the nearest rank', () => {
    const samples = Array.from({ length: 100 }, (_, i) => 100 - i);
    expect(percentile(samples, 50)).toBe(50);
    expect(percentile(samples, 99)).toBe(99);
    expect(percentile(samples, 100)).toBe(100);
  });
});

describe('stolenMsFromProcStat', () => {
  it('reads the steal column of the cpu line, in ms', () => {
    const text = [
      'cpu  1965852 7910 314332 11104267 7769 0 6160 254633 0 0',
      'cpu0 982926 3955 157166 5552133 3884 0 3080 127316 0 0',
      'intr 1',
    ].join('\n');
    expect(stolenMsFromProcStat(text)).toBe(2_546_330);
  });

  it('is undefined for a kernel without the column or without the line', () => {
    expect(stolenMsFromProcStat('cpu  1 2 3 4\n')).toBeUndefined();
    expect(stolenMsFromProcStat('intr 1\n')).toBeUndefined();
  });
});

describe('writeReport', () => {
  let dir: string | undefined;
  afterEach(async () => {
    if (dir !== undefined) await rm(dir, { recursive: true, force: true });
  });

  it('writes the figures table, the machine and one SVG per plot', async () => {
    dir = await mkdtemp(join(tmpdir(), 'bench-report-'));
    const points = [10, 100, 1000].map((x) => ({
      kind: 'point' as const,
      plot: 'sim-scaling',
      title: 'Simulation speed by robot count',
      series: 'event stepping',
      x,
      y: 1e6 / x,
      xLabel: 'robots',
      yLabel: 'robot-seconds per second',
      logX: true,
      logY: true,
    }));
    const outcome = await writeReport(dir, [
      { bench: 'physical', ok: true, records: [latency, ...points], malformed: [], seconds: 3 },
      { bench: 'broken', ok: false, records: [], malformed: [], seconds: 1 },
    ]);
    expect(outcome).toBe('1 benchmark(s) failed');
    const readme = await readFile(join(dir, 'README.md'), 'utf8');
    expect(readme).toContain('UDP round trip p99');
    expect(readme).toContain(`Node ${process.version}`);
    expect(readme).toContain('![sim-scaling](sim-scaling.svg)');
    expect(readme).toContain('| broken | FAILED |');
    expect(await readdir(dir)).toContain('sim-scaling.svg');
    const svg = await readFile(join(dir, 'sim-scaling.svg'), 'utf8');
    expect(svg.startsWith('<svg')).toBe(true);
    expect(svg).toContain('Simulation speed by robot count');
  });
});
