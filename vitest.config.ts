import { readdirSync } from 'node:fs';
import { defineConfig } from 'vitest/config';

const packageNames = readdirSync(new URL('./packages', import.meta.url));

// Everything inside the repository runs from source through the "@hal/source" export condition,
// so no test needs a build step.
export default defineConfig({
  resolve: { conditions: ['@hal/source'] },
  ssr: { resolve: { conditions: ['@hal/source'] } },
  test: {
    setupFiles: ['./vitest.setup.ts'],
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
          testTimeout: 60_000,
          hookTimeout: 60_000,
        },
      },
    ],
  },
});
