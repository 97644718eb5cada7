// The browser demo's Remote robot card in Chromium: hal-serve (the one command) serves PhysicalHAL
// to the emulated robot with a token; the page connects with the URL and token fields, drives it
// through a HybridHAL whose twin is the page's simulated robot, and shows their divergence.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import type { BrowserContext, Page } from 'playwright-core';
import { build, preview } from 'vite';
import type { PreviewServer } from 'vite';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startHalServe, stopAllHalServes } from '../remote/hal-serve.js';
import { requireChromium } from './chromium.js';

const demoRoot = join(fileURLToPath(new URL('../..', import.meta.url)), 'apps/sim-demo');

interface RemoteState {
  connection: string;
  role: string;
  pose: { x: number; y: number; yaw: number } | null;
  divergence: { positionM: number; yawRad: number; exceeded: boolean } | null;
  lastResult: { call: string; success: boolean; code?: string } | null;
}
type Hooked = { simDemo?: { remote(): RemoteState } };

describe('apps/sim-demo Remote robot card in Chromium', () => {
  let server: PreviewServer;
  let context: BrowserContext;
  let page: Page;
  let outDir: string;
  let profile: string;
  const problems: string[] = [];

  beforeAll(async () => {
    const executablePath = requireChromium();
    outDir = mkdtempSync(join(tmpdir(), 'remote-demo-build-'));
    profile = mkdtempSync(join(tmpdir(), 'remote-demo-profile-'));
    await build({
      root: demoRoot,
      configFile: join(demoRoot, 'vite.config.ts'),
      logLevel: 'silent',
      build: { outDir, emptyOutDir: true },
    });
    server = await preview({
      root: demoRoot,
      configFile: join(demoRoot, 'vite.config.ts'),
      logLevel: 'silent',
      build: { outDir },
      preview: { host: '127.0.0.1', port: 0, strictPort: false },
    });
    context = await chromium.launchPersistentContext(profile, {
      executablePath,
      headless: true,
      viewport: { width: 1400, height: 1000 },
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'],
    });
    page = context.pages()[0] ?? (await context.newPage());
    page.on('console', (message) => {
      if (message.type() === 'error') problems.push(`console.error: ${message.text()}`);
    });
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  }, 90_000);

  afterAll(async () => {
    await context?.close();
    await server?.close();
    stopAllHalServes();
    await stopAllEmulators();
    if (outDir !== undefined) rmSync(outDir, { recursive: true, force: true });
    if (profile !== undefined) rmSync(profile, { recursive: true, force: true });
  }, 30_000);

  const remoteState = () => page.evaluate(() => (window as unknown as Hooked).simDemo?.remote());

  it('connects with URL and token, moves the emulated robot and its twin, and shows the divergence', async () => {
    const token = 'browser-demo-token-123';
    const emulator = await startEmulator({ pty: false, hostTimeoutMs: 10_000 });
    const wsUrl = await startHalServe(
      ['--udp', `127.0.0.1:${emulator.udpPort}`, '--device-id', 'cube-remote'],
      {
        HAL_SERVE_TOKEN: token,
      },
    );
    const url = server.resolvedUrls?.local[0];
    expect(url).toBeDefined();
    await page.goto(`${url}?map=empty`, { waitUntil: 'load', timeout: 20_000 });
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo !== undefined,
      undefined,
      {
        timeout: 15_000,
      },
    );

    // A wrong token is refused and said so.
    await page.locator('#remote-url').fill(wsUrl);
    await page.locator('#remote-token').fill('not-the-right-token');
    await page.locator('#remote-connect').click();
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo?.remote().connection === 'failed',
      undefined,
      { timeout: 15_000 },
    );

    await page.locator('#remote-token').fill(token);
    await page.locator('#remote-connect').click();
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo?.remote().connection === 'connected',
      undefined,
      { timeout: 15_000 },
    );
    expect((await remoteState())?.role).toBe('controller');
    await expect(page.locator('#remote-badge').textContent()).resolves.toBe('CONNECTED');

    await page.locator('[data-remote="forward"]').click();
    await page.waitForFunction(
      () => (window as unknown as Hooked).simDemo?.remote().lastResult?.call === 'forward',
      undefined,
      { timeout: 30_000 },
    );
    await page.waitForFunction(
      () => ((window as unknown as Hooked).simDemo?.remote().pose?.x ?? 0) > 0.09,
      undefined,
      { timeout: 5_000 },
    );
    const state = await remoteState();
    expect(state?.lastResult).toEqual({ call: 'forward', success: true });
    expect(state?.pose?.x).toBeCloseTo(0.1, 2);
    expect(state?.divergence).toMatchObject({ exceeded: false });
    expect(state?.divergence?.positionM).toBeLessThan(0.005);
    await expect(page.locator('#remote-info').textContent()).resolves.toMatch(/Twin divergence\d/);
    expect(emulator.events.filter((e) => e.event === 'move_finished')).toHaveLength(1);

    // The e-stop button latches the remote robot; the badge says so.
    await page.locator('[data-remote="estop"]').click();
    await page.waitForFunction(
      () => document.getElementById('remote-badge')?.textContent === 'E-STOP',
      undefined,
      { timeout: 5_000 },
    );
    // The only console error is the browser's own report of the refused wrong token.
    expect(problems.filter((p) => !p.includes('not-the-right-token'))).toEqual([]);
  }, 150_000);
});
