// The browser demo as the end-to-end tests meet it: built and served once per run by the e2e
// project's global setup (demo-server.global.ts), and opened here in Debian's Chromium (driven by
// playwright-core) with a throwaway profile. Console errors and page errors are collected, so a
// test can assert that there were none.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';
import type { BrowserContext, Page } from 'playwright-core';
import { inject } from 'vitest';
import { CHROMIUM_FLAGS, requireChromium } from './chromium.js';

export interface DemoBrowser {
  /** The served demo's URL. */
  url: string;
  page: Page;
  /** Console errors and page errors, in order. */
  problems: string[];
  /** Closes the browser and removes its profile (the shared server stays up for the run). */
  close(): Promise<void>;
}

/** Opens Chromium on a blank page, beside the run's served demo (the test navigates). */
export async function openDemoInChromium(
  name: string,
  viewport: { width: number; height: number } = { width: 1400, height: 900 },
): Promise<DemoBrowser> {
  const executablePath = requireChromium();
  const url = inject('demoUrl');
  const profile = mkdtempSync(join(tmpdir(), `${name}-profile-`));
  let context: BrowserContext | undefined;
  const close = async () => {
    await context?.close();
    rmSync(profile, { recursive: true, force: true });
  };
  try {
    context = await chromium.launchPersistentContext(profile, {
      executablePath,
      headless: true,
      viewport,
      args: [...CHROMIUM_FLAGS],
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
