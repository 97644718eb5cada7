// Runs every benchmark in bench/ (files named *.bench.ts, each a standalone program that prints
// its figures), one after another, or only those whose names contain the given words. A full run
// (no words given) also writes the report, bench/results/README.md, with every figure and plot.
import { spawn } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { ensureEmulatorFor } from './ensure-emulator.js';
import { collectRecords } from './report/collect.js';
import { BENCH_JSON_PREFIX } from './report/figures.js';
import { writeReport } from './report/write.js';
import type { BenchRun } from './report/write.js';

const dir = fileURLToPath(new URL('.', import.meta.url));
const filters = process.argv.slice(2);
const files = readdirSync(dir)
  .filter((name) => name.endsWith('.bench.ts'))
  .filter((name) => filters.length === 0 || filters.some((f) => name.includes(f)))
  .sort();
ensureEmulatorFor(dir, files); // builds cube-emulator when a selected benchmark starts it

/** Runs one benchmark, echoing its human-readable lines and keeping all its output. */
function runBench(file: string): Promise<BenchRun> {
  const started = performance.now();
  return new Promise((resolve) => {
    const child = spawn(
      process.execPath,
      ['--conditions=@hal/source', '--import', 'tsx', `${dir}${file}`],
      { stdio: ['ignore', 'pipe', 'inherit'] },
    );
    let output = '';
    let partial = '';
    child.stdout.setEncoding('utf8');
    child.stdout.on('data', (chunk: string) => {
      output += chunk;
      const lines = (partial + chunk).split('\n');
      partial = lines.pop() ?? '';
      for (const line of lines) if (!line.startsWith(BENCH_JSON_PREFIX)) console.log(line);
    });
    child.on('close', (code) => {
      if (partial !== '' && !partial.startsWith(BENCH_JSON_PREFIX)) console.log(partial);
      const { records, malformed } = collectRecords(output);
      resolve({
        bench: file.replace(/\.bench\.ts$/, ''),
        ok: code === 0,
        records,
        malformed,
        seconds: (performance.now() - started) / 1000,
      });
    });
  });
}

const runs: BenchRun[] = [];
for (const file of files) {
  console.log(`\n=== ${file} ===`);
  runs.push(await runBench(file));
}
for (const run of runs) {
  for (const line of run.malformed) console.error(`${run.bench}: malformed record: ${line}`);
}
if (filters.length === 0) {
  const outcome = await writeReport(`${dir}results`, runs);
  console.log(`\nreport: bench/results/README.md (${outcome})`);
}
process.exit(runs.every((run) => run.ok && run.malformed.length === 0) ? 0 : 1);
