import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as simulation from '@hal/simulation';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { expect, it } from 'vitest';
import * as recorder from './index.js';

const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');

it('README: records a simulated run to a file and reads it back with nothing dropped', async () => {
  const blocks = fencedBlocks(readme, 'ts');
  expect(blocks).toHaveLength(1);
  const dir = mkdtempSync(join(tmpdir(), 'hal-recorder-'));
  try {
    const code = blocks[0]!.replaceAll("'run.mcap'", JSON.stringify(join(dir, 'run.mcap')));
    const logged: unknown[][] = [];
    await runDocExample(
      code.replaceAll('console.log(', 'log('),
      { '@hal/recorder': recorder, '@hal/simulation': simulation },
      { log: (...values: unknown[]) => logged.push(values) },
    );
    // initialize, moveForward, emergencyStop, cleanup
    expect(logged).toEqual([[0, 4]]);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
