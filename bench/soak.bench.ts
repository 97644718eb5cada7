// Soak: 10,000 commands through PhysicalHAL in a host process, over UDP and over the emulator's
// pseudo-terminal, interleaved (udp, serial, udp, serial): throughput, latency of single-request
// calls (p50/p99), and the resident memory of the host (after a full GC) and of the emulator,
// after warm-up and at the end. SOAK_COUNT and SOAK_ROUNDS change the size.
import { runSoak } from '../tests/physical/soak.js';
import type { SoakLink, SoakReport } from '../tests/physical/soak.js';
import { reportFigure } from './report/figures.js';

const COUNT = Number(process.env['SOAK_COUNT'] ?? 10_000);
const ROUNDS = Number(process.env['SOAK_ROUNDS'] ?? 2);
const TIME_SCALE = 10;

const mb = (bytes: number) => `${(bytes / 1048576).toFixed(1)} MB`;
const ms = (value: number) => `${value.toFixed(2)} ms`;

const reports: SoakReport[] = [];
for (let round = 0; round < ROUNDS; round++) {
  for (const link of ['udp', 'serial'] as SoakLink[]) {
    const r = await runSoak({ link, count: COUNT, timeScale: TIME_SCALE, maxSeconds: 600 });
    reports.push(r);
    console.log(
      `${link.padEnd(6)} ${r.commands} commands (${r.motions} moves) in ${r.seconds.toFixed(1)} s after warm-up: ` +
        `${r.perSecond.toFixed(0)} commands/s, p50 ${ms(r.p50Ms)}, p99 ${ms(r.p99Ms)}; ` +
        `failed ${r.failed}, lost replies ${r.timeouts}, retries ${r.retries}, trips ${r.trips}; ` +
        `steps ${r.robot.left}/${r.robot.right} (expected ${r.expected.left}/${r.expected.right})`,
    );
    console.log(
      `       RSS host ${mb(r.host.rssStart)} -> ${mb(r.host.rssEnd)} (heap ${mb(r.host.heapStart)} -> ${mb(r.host.heapEnd)}), ` +
        `emulator ${mb(r.emulator.rssStart)} -> ${mb(r.emulator.rssEnd)}`,
    );
  }
}

const median = (values: number[]) => {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)] ?? 0;
};
const rate = (link: SoakLink) =>
  median(reports.filter((r) => r.link === link).map((r) => r.perSecond));
const p50 = (link: SoakLink) => median(reports.filter((r) => r.link === link).map((r) => r.p50Ms));
console.log(
  `ratio serial/udp: throughput ${(rate('serial') / rate('udp')).toFixed(2)}x, p50 latency ${(p50('serial') / p50('udp')).toFixed(2)}x`,
);

// The figures, per link: the median of the rounds for speed and latency, the round whose memory
// grew most for RSS, and the lost replies of all rounds.
const MB = 1048576;
for (const link of ['udp', 'serial'] as SoakLink[]) {
  const runs = reports.filter((r) => r.link === link);
  const of = (value: (r: SoakReport) => number) => median(runs.map(value));
  const rounds = `median of ${runs.length} rounds of ${COUNT} commands, each a fresh host process and emulator (time scale ${TIME_SCALE}), udp and serial interleaved`;
  reportFigure({
    bench: 'soak',
    name: `${link}: commands through PhysicalHAL per second`,
    value: of((r) => r.perSecond),
    unit: 'commands/s',
    better: 'higher',
    note: rounds,
  });
  for (const [stat, value] of [
    ['p50', (r: SoakReport) => r.p50Ms],
    ['p99', (r: SoakReport) => r.p99Ms],
  ] as const) {
    reportFigure({
      bench: 'soak',
      name: `${link}: single-request call latency ${stat}`,
      value: of(value),
      unit: 'ms',
      better: 'lower',
      note: rounds,
    });
  }
  for (const [process, rss] of [
    ['host', (r: SoakReport) => r.host],
    ['emulator', (r: SoakReport) => r.emulator],
  ] as const) {
    const worst = runs.reduce<SoakReport | undefined>(
      (a, r) =>
        a === undefined || rss(r).rssEnd / rss(r).rssStart > rss(a).rssEnd / rss(a).rssStart
          ? r
          : a,
      undefined,
    );
    if (worst === undefined) continue;
    reportFigure({
      bench: 'soak',
      name: `${link}: ${process} RSS at the end`,
      value: rss(worst).rssEnd / MB,
      unit: 'MB',
      better: 'lower',
      alternative: { name: 'at start (after warm-up)', value: rss(worst).rssStart / MB },
      note: `the round (of ${runs.length}) whose ${process} memory grew most, ${COUNT} commands${process === 'host' ? ', after a full GC' : ''}`,
    });
  }
  reportFigure({
    bench: 'soak',
    name: `${link}: lost replies (requests given up after every attempt)`,
    value: runs.reduce((sum, r) => sum + r.timeouts, 0),
    unit: 'replies',
    better: 'lower',
    note: `all ${runs.length} rounds of ${COUNT} commands`,
  });
}
