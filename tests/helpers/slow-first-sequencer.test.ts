// The run's order: the files known to take longest start first, longest first, ahead of files
// vitest knows nothing of; a time from vitest's results cache counts before the list's.
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import type { TestSpecification, Vitest } from 'vitest/node';
import { SLOW_FILES, SlowFirstSequencer } from './slow-first-sequencer.js';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** A sequencer over a results cache holding `cachedMs` and files of the given sizes. */
function sequencer(cachedMs: Record<string, number>, sizes: Record<string, number>) {
  const fileOf = (key: string) => key.slice(key.indexOf(':') + 1);
  const ctx = {
    config: { root },
    cache: {
      getFileTestResults: (key: string) =>
        cachedMs[fileOf(key)] === undefined
          ? undefined
          : { duration: cachedMs[fileOf(key)], failed: false },
      getFileStats: (key: string) => ({ size: sizes[fileOf(key)] ?? 0 }),
    },
  };
  return new SlowFirstSequencer(ctx as unknown as Vitest);
}

const spec = (file: string) =>
  ({ moduleId: join(root, file), project: { name: 'tests' } }) as unknown as TestSpecification;
const files = (specs: TestSpecification[]) => specs.map((s) => s.moduleId.slice(root.length));

describe('SlowFirstSequencer', () => {
  it('lists only files that exist', () => {
    const missing = Object.keys(SLOW_FILES).filter((file) => !existsSync(join(root, file)));
    expect(missing).toEqual([]);
  });

  it('starts the listed files first, longest first, then the rest in vitest order (largest first)', async () => {
    const sorted = await sequencer(
      {},
      { 'tests/small.test.ts': 100, 'tests/large.test.ts': 9000 },
    ).sort(
      [
        'tests/small.test.ts',
        'tests/docs/doc-commands.test.ts',
        'tests/large.test.ts',
        'tests/publish/installs.test.ts',
      ].map(spec),
    );
    expect(files(sorted)).toEqual([
      'tests/publish/installs.test.ts',
      'tests/docs/doc-commands.test.ts',
      'tests/large.test.ts',
      'tests/small.test.ts',
    ]);
  });

  it("takes a file's time from the results cache before the list's", async () => {
    const sorted = await sequencer({ 'tests/small.test.ts': 500_000 }, {}).sort(
      ['tests/publish/installs.test.ts', 'tests/small.test.ts'].map(spec),
    );
    expect(files(sorted)).toEqual(['tests/small.test.ts', 'tests/publish/installs.test.ts']);
  });
});
