// The example of the README, run as written, so it cannot rot.
import { readFileSync } from 'node:fs';
import * as simulation from '@hal/simulation';
import type { ExampleModules } from '@hal/types/testing';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { describe, expect, it } from 'vitest';
import * as fleet from './index.js';

const MODULES: ExampleModules = {
  '@hal/fleet': fleet,
  '@hal/simulation': simulation,
};

const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');

describe('the README example', () => {
  it('prints what the README says it prints', async () => {
    const [code] = fencedBlocks(readme, 'ts');
    const [expected] = fencedBlocks(readme, 'text');
    const lines: string[] = [];
    const log = (...values: unknown[]) => lines.push(values.map(String).join(' '));
    await runDocExample(code ?? '', MODULES, { console: { log } });
    expect(`${lines.join('\n')}\n`).toBe(expected);
  }, 60_000);
});
