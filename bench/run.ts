// Runs every benchmark in bench/ (files named *.bench.ts, each a standalone program that prints
// its figures), one after another, or only those whose names contain the given words.
import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { ensureEmulatorFor } from './ensure-emulator.js';

const dir = fileURLToPath(new URL('.', import.meta.url));
const filters = process.argv.slice(2);
const files = readdirSync(dir)
  .filter((name) => name.endsWith('.bench.ts'))
  .filter((name) => filters.length === 0 || filters.some((f) => name.includes(f)))
  .sort();
ensureEmulatorFor(dir, files); // builds cube-emulator when a selected benchmark starts it

let failed = 0;
for (const file of files) {
  console.log(`\n=== ${file} ===`);
  const run = spawnSync(
    process.execPath,
    ['--conditions=@hal/source', '--import', 'tsx', `${dir}${file}`],
    {
      stdio: 'inherit',
    },
  );
  if (run.status !== 0) failed += 1;
}
process.exit(failed === 0 ? 0 : 1);
