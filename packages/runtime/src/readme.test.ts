import * as types from '@hal/types';
import { fencedBlocks, runDocExample } from '@hal/types/testing';
import { readFileSync } from 'node:fs';
import { expect, it } from 'vitest';
import * as runtime from './index.js';

it('README: a robot of your own is a RobotPort, driven by RobotHAL', async () => {
  const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');
  const [example] = fencedBlocks(readme, 'ts');
  const logged: unknown[][] = [];
  await runDocExample(
    example ?? '',
    { '@hal/runtime': runtime, '@hal/types': types },
    { log: (...values: unknown[]) => logged.push(values) },
  );
  const [moves, pose] = logged[0] ?? [];
  expect(moves).toBe(2);
  expect(pose).toMatchObject({ x: expect.closeTo(0.3, 9), y: expect.closeTo(0.4, 9) });
  expect(logged[1]).toEqual(['RANGE_EXCEEDED']);
});
