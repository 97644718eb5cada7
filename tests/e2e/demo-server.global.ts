// Global setup of the e2e project: the browser demo built once with vite into a temporary folder
// and served by vite's preview server on a free port of 127.0.0.1, for every browser test of the
// run. Each test opens its own Chromium profile on it (demo-browser.ts), so the tests share the
// build and the server but nothing a page can change.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build, preview } from 'vite';
import type { PreviewServer } from 'vite';
import type { TestProject } from 'vitest/node';

declare module 'vitest' {
  export interface ProvidedContext {
    /** The served demo's URL, e.g. `http://127.0.0.1:4173/`. */
    demoUrl: string;
  }
}

const demoRoot = join(fileURLToPath(new URL('../..', import.meta.url)), 'apps/sim-demo');

export default async function serveDemo(project: TestProject): Promise<() => Promise<void>> {
  const outDir = mkdtempSync(join(tmpdir(), 'sim-demo-build-'));
  let server: PreviewServer | undefined;
  const teardown = async () => {
    await server?.close();
    rmSync(outDir, { recursive: true, force: true });
  };
  try {
    const configFile = join(demoRoot, 'vite.config.ts');
    await build({
      root: demoRoot,
      configFile,
      logLevel: 'silent',
      build: { outDir, emptyOutDir: true },
    });
    server = await preview({
      root: demoRoot,
      configFile,
      logLevel: 'silent',
      build: { outDir },
      preview: { host: '127.0.0.1', port: 0, strictPort: false },
    });
    const url = server.resolvedUrls?.local[0];
    if (url === undefined) throw new Error('the preview server of the demo has no URL');
    project.provide('demoUrl', url);
    return teardown;
  } catch (error) {
    await teardown();
    throw error;
  }
}
