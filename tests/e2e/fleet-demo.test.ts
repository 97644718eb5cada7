// The browser demo with several robots in one world, in a real browser (Debian's Chromium driven
// by playwright-core): robots are added and labelled, the panels drive the selected one, and the
// Fleet card runs the fleet modes of @hal/fleet over the robots' HALs. Saves a screenshot to
// artifacts/fleet-demo.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const artifacts = join(repoRoot, 'artifacts');

interface RobotView {
  id: string;
  label: string;
  x: number;
  y: number;
  yaw: number;
  running: boolean;
  emergencyStopped: boolean;
}

interface FleetDemoHooks {
  robotId: string;
  robots(): RobotView[];
}

/** The page's window with the demo's hooks (functions passed to the page must name it inline). */
type DemoWindow = { simDemo: FleetDemoHooks };

describe('apps/sim-demo with several robots, in Chromium', () => {
  let demo: DemoBrowser;
  let page: Page;

  beforeAll(async () => {
    demo = await openDemoInChromium('fleet-demo');
    page = demo.page;
    // The empty map: room for a formation; three robots to start with.
    await page.goto(`${demo.url}?map=empty&speed=20&robots=3`, {
      waitUntil: 'load',
      timeout: 20_000,
    });
    await page.waitForFunction(
      () => (window as unknown as { simDemo?: unknown }).simDemo !== undefined,
      undefined,
      { timeout: 15_000 },
    );
  }, 60_000);

  afterAll(async () => {
    await demo?.close();
  }, 30_000);

  const robots = () => page.evaluate(() => (window as unknown as DemoWindow).simDemo.robots());

  it('shows each robot labelled in its place, adds one, and drives only the selected one', async () => {
    let all = await robots();
    expect(all.map((r) => r.label)).toEqual(['R1', 'R2', 'R3']);
    await expect(page.locator('.robot-label').allTextContents()).resolves.toEqual([
      'R1',
      'R2',
      'R3',
    ]);
    await page.locator('#add-robot').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.robots().length === 4,
      undefined,
      { timeout: 5_000 },
    );
    all = await robots();
    // Apart from each other: no two footprints (7 cm radius) touch.
    for (const a of all) {
      for (const b of all) {
        if (a !== b) expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeGreaterThan(0.14);
      }
    }
    expect(await page.locator('#robot-count').textContent()).toContain('4 of 8 · R4 selected');

    // Select R2 and drive it with the keyboard: only R2 moves.
    await page.locator('.robot-item[data-robot-id="robot-2"]').click();
    expect(await page.evaluate(() => (window as unknown as DemoWindow).simDemo.robotId)).toBe(
      'robot-2',
    );
    const before = await robots();
    await page.locator('#viewport > canvas').focus();
    await page.keyboard.down('ArrowUp');
    await page.waitForFunction(
      (x0) => ((window as unknown as DemoWindow).simDemo.robots()[1]?.x ?? 0) > x0 + 0.05,
      before[1]?.x ?? 0,
      { timeout: 20_000 },
    );
    await page.keyboard.up('ArrowUp');
    await page.waitForFunction(
      () => !(window as unknown as DemoWindow).simDemo.robots()[1]?.running,
      undefined,
      {
        timeout: 10_000,
      },
    );
    const after = await robots();
    for (const i of [0, 2, 3]) {
      expect(after[i]?.x).toBe(before[i]?.x);
      expect(after[i]?.y).toBe(before[i]?.y);
    }
    expect(demo.problems).toEqual([]);
  }, 120_000);

  it('saves a screenshot with no console errors', async () => {
    mkdirSync(artifacts, { recursive: true });
    await page.screenshot({ path: join(artifacts, 'fleet-demo.png') });
    expect(demo.problems).toEqual([]);
  });
});
