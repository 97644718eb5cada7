// The browser demo as the end-to-end tests meet it: built with vite into a temporary folder,
// served by vite's preview server on a free port of 127.0.0.1, and opened in Debian's Chromium
// (driven by playwright-core) with a throwaway profile. Console errors and page errors are
// collected, so a test can assert that there were none.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import type { BrowserContext, Page } from 'playwright-core';
import { build, preview } from 'vite';
import type { PreviewServer } from 'vite';
import { requireChromium } from './chromium.js';

const demoRoot = join(fileURLToPath(new URL('../..', import.meta.url)), 'apps/sim-demo');

export interface DemoBrowser {
  /** The served demo's URL. */
  url: string;
  page: Page;
  /** Console errors and page errors, in order. */
  problems: string[];
  /** Closes the browser and the server and removes the build and the profile. */
  close(): Promise<void>;
}

/** Builds and serves the demo, and opens Chromium on a blank page (the test navigates). */
export async function openDemoInChromium(
  name: string,
  viewport: { width: number; height: number } = { width: 1400, height: 900 },
): Promise<DemoBrowser> {
  const executablePath = requireChromium();
  const outDir = mkdtempSync(join(tmpdir(), `${name}-build-`));
  const profile = mkdtempSync(join(tmpdir(), `${name}-profile-`));
  let server: PreviewServer | undefined;
  let context: BrowserContext | undefined;
  const close = async () => {
    await context?.close();
    await server?.close();
    rmSync(outDir, { recursive: true, force: true });
    rmSync(profile, { recursive: true, force: true });
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
    if (url === undefined) throw new Error('the preview server has no URL');
    context = await chromium.launchPersistentContext(profile, {
      executablePath,
      headless: true,
      viewport,
      args: [
        '--headless',
        '--no-sandbox',
        '--disable-gpu',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
        '--no-first-run',
      ],
    });
    const page = context.pages()[0] ?? (await context.newPage());
    const problems: string[] = [];
    page.on('console', (message) => {
      if (message.type() === 'error') problems.push(`console.error: ${message.text()}`);
    });
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    return { url, page, problems, close };
  } catch (error) {
    await close();
    throw error;
  }
}
