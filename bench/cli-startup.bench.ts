// How long `hal --help` takes from a checkout: the launcher (scripts/hal.js, one bundled file,
// what `pnpm hal` runs) against the sources through tsx (what `pnpm hal` ran before), interleaved
// round by round, with `pnpm hal --help` (pnpm's own start-up included) and a bare `node -e 0`
// beside them so the floor is visible. Each round is a fresh process, as a user's command is.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { percentile, reportFigure } from './report/figures.js';

const root = fileURLToPath(new URL('..', import.meta.url));
const rounds = Number(process.env['CLI_STARTUP_ROUNDS'] ?? 15);

interface Variant {
  name: string;
  command: string;
  args: string[];
  samples: number[];
}

const variants: Variant[] = [
  { name: 'launcher', command: process.execPath, args: ['scripts/hal.js', '--help'], samples: [] },
  {
    name: 'tsx from source',
    command: process.execPath,
    args: ['--conditions=@hal/source', '--import', 'tsx', 'packages/cli/src/main.ts', '--help'],
    samples: [],
  },
  { name: 'pnpm hal', command: 'pnpm', args: ['-s', 'hal', '--help'], samples: [] },
  { name: 'node -e 0', command: process.execPath, args: ['-e', '0'], samples: [] },
];

function timeOnce(variant: Variant): number {
  const started = performance.now();
  const run = spawnSync(variant.command, variant.args, { cwd: root, encoding: 'utf8' });
  const ms = performance.now() - started;
  if (run.status !== 0 || (variant.name !== 'node -e 0' && !run.stdout.includes('Usage: hal'))) {
    throw new Error(`${variant.name}: exited ${run.status}: ${run.stderr}`);
  }
  return ms;
}

// one untimed run each: the launcher bundles here if its sources changed, tsx fills its cache
for (const variant of variants) timeOnce(variant);
for (let round = 0; round < rounds; round += 1) {
  for (const variant of variants) variant.samples.push(timeOnce(variant));
}

const median = (v: Variant): number => percentile(v.samples, 50);
const [launcher, tsx, viaPnpm, floor] = variants as [Variant, Variant, Variant, Variant];
for (const v of variants) {
  console.log(
    `${v.name.padEnd(16)} p50 ${median(v).toFixed(0).padStart(5)} ms  p90 ${percentile(
      v.samples,
      90,
    )
      .toFixed(0)
      .padStart(5)} ms  (${rounds} rounds)`,
  );
}
console.log(`launcher / tsx from source: ${(median(launcher) / median(tsx)).toFixed(2)}x`);

reportFigure({
  bench: 'cli-startup',
  name: 'hal --help through the launcher, p50',
  value: median(launcher),
  unit: 'ms',
  better: 'lower',
  alternative: { name: 'tsx from source', value: median(tsx) },
  goal: '<= 300 ms',
  met: median(launcher) <= 300,
  note: `a fresh process per run, ${rounds} interleaved rounds; node -e 0 took ${median(floor).toFixed(0)} ms p50`,
});
reportFigure({
  bench: 'cli-startup',
  name: 'pnpm hal --help, p50',
  value: median(viaPnpm),
  unit: 'ms',
  better: 'lower',
  alternative: { name: 'launcher without pnpm', value: median(launcher) },
  note: "the difference is pnpm's own start-up, outside the project",
});
