import { readdirSync } from 'node:fs';
import { configDefaults, defineConfig } from 'vitest/config';
import { SlowFirstSequencer } from './tests/helpers/slow-first-sequencer.js';

const packageNames = readdirSync(new URL('./packages', import.meta.url));

// Everything inside the repository runs from source through the "@hal/source" export condition,
// so no test needs a build step.
export default defineConfig({
  resolve: { conditions: ['@hal/source'] },
  ssr: { resolve: { conditions: ['@hal/source'] } },
  test: {
    setupFiles: ['./vitest.setup.ts'],
    // Four files at a time: most cross-process files spend their time waiting on the emulator,
    // nats-server, Chromium or a child `hal`, so workers beyond the two cores keep the cores busy
    // (vitest's default on two cores is one worker). On a 2-core machine, in one full run each:
    // 378 s with three workers, 330 s with four, with the cores still 15 % idle.
    maxWorkers: 4,
    // The files of minutes first, so that none starts last and runs alone at the end.
    sequence: { sequencer: SlowFirstSequencer },
    // A timeout is there to catch a hang, not to time a test: the CPU-bound property and
    // simulation tests take seconds, and several times that on a loaded 2-core machine, past
    // vitest's default of 5 s.
    testTimeout: 30_000,
    hookTimeout: 30_000,
    projects: [
      ...packageNames.map((name) => ({
        extends: true as const,
        test: { name, include: [`packages/${name}/src/**/*.test.ts`] },
      })),
      {
        extends: true as const,
        test: { name: 'apps', include: ['apps/*/src/**/*.test.ts'] },
      },
      {
        extends: true as const,
        test: { name: 'bench', include: ['bench/**/*.test.ts'] },
      },
      {
        extends: true as const,
        test: {
          name: 'tests',
          include: ['tests/**/*.test.ts'],
          exclude: [...configDefaults.exclude, 'tests/e2e/**'],
          // a folder for the run, where the tests of the packed tarballs pack the packages and
          // install the app with every tarball once for all of them (tests/publish/shared.ts)
          globalSetup: ['tests/publish/published.global.ts'],
          testTimeout: 60_000,
          hookTimeout: 60_000,
        },
      },
      {
        // The browser tests: one build and one preview server of the demo for all of them.
        extends: true as const,
        test: {
          name: 'e2e',
          include: ['tests/e2e/**/*.test.ts'],
          globalSetup: ['tests/e2e/demo-server.global.ts'],
          testTimeout: 60_000,
          hookTimeout: 60_000,
        },
      },
    ],
  },
});
