import { readFileSync } from 'node:fs';
import * as simulation from '@hal/simulation';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { expect, it } from 'vitest';
import * as foxglove from './index.js';

const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');

it('README: serves a simulated robot live on a free loopback port and closes', async () => {
  const blocks = fencedBlocks(readme, 'ts');
  expect(blocks).toHaveLength(1);
  const logged: unknown[][] = [];
  await runDocExample(
    blocks[0]!.replaceAll('console.log(', 'log('),
    { '@hal/foxglove': foxglove, '@hal/simulation': simulation },
    { log: (...values: unknown[]) => logged.push(values) },
  );
  expect(logged).toHaveLength(2);
  expect(String(logged[0]![0])).toMatch(/^ws:\/\/127\.0\.0\.1:\d+$/);
  expect(logged[1]).toEqual([0]);
});
