// The browser demo as a user's browser gets it: built with vite into a temporary folder and served
// by vite's preview server on a free port of 127.0.0.1. The e2e project's global setup serves it
// once for all the browser tests; the render benchmark serves it for its own run.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build, preview } from 'vite';
import type { PreviewServer } from 'vite';

const demoRoot = join(fileURLToPath(new URL('../..', import.meta.url)), 'apps/sim-demo');

export interface ServedDemo {
  /** The served demo's URL, e.g. `http://127.0.0.1:4173/`. */
  url: string;
  /** Stops the server and removes the build. */
  close(): Promise<void>;
}

/** Builds the demo and serves the build; on a failure, removes what it made and throws. */
export async function serveBuiltDemo(): Promise<ServedDemo> {
  const outDir = mkdtempSync(join(tmpdir(), 'sim-demo-build-'));
  let server: PreviewServer | undefined;
  const close = async () => {
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
    return { url, close };
  } catch (error) {
    await close();
    throw error;
  }
}
