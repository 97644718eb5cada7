// The browser demo in a real browser: Debian's Chromium driven by playwright-core. Builds the
// demo, serves it on a free port, and checks that the page loads without console errors, that
// keyboard teleop moves the robot, and that clicked goals are reached, by a straight moveTo and
// by the navigation bridge around an obstacle. Saves a screenshot to artifacts/sim-demo.png.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const artifacts = join(repoRoot, 'artifacts');

interface DemoHooks {
  robotId: string;
  goalState(): string;
  pose(): { x: number; y: number; yaw: number };
  framesDrawn(): number;
  render(): { name: string; rendererName?: string; minFrameIntervalMs: number };
  worldToClient(x: number, y: number): { x: number; y: number };
}

declare global {
  interface Window {
    simDemo?: DemoHooks;
  }
}

describe('apps/sim-demo in Chromium', () => {
  let demo: DemoBrowser;
  let page: Page;

  beforeAll(async () => {
    demo = await openDemoInChromium('sim-demo');
    page = demo.page;
  }, 60_000);

  afterAll(async () => {
    await demo?.close();
  }, 30_000);

  async function clickGoal(x: number, y: number): Promise<void> {
    const at = await page.evaluate(([gx, gy]) => window.simDemo?.worldToClient(gx, gy), [
      x,
      y,
    ] as const);
    expect(at).toBeDefined();
    await page.mouse.click(at?.x ?? 0, at?.y ?? 0);
    await page.waitForFunction(() => window.simDemo?.goalState() === 'driving', undefined, {
      timeout: 5_000,
    });
    await page.waitForFunction(() => window.simDemo?.goalState() !== 'driving', undefined, {
      timeout: 40_000,
    });
  }

  it('loads without console errors, moves by keyboard and reaches clicked goals', async () => {
    const { url, problems } = demo;
    // The obstacles map: the robot starts at (-1.8, 0) facing +x, a box spans x -1.1..-0.7.
    await page.goto(`${url}?map=obstacles&speed=20`, { waitUntil: 'load', timeout: 20_000 });
    await page.waitForFunction(() => window.simDemo !== undefined, undefined, { timeout: 15_000 });

    // Nothing moves: the view is drawn on demand, about once a second. (A page drawing every
    // frame would have drawn ~120 in these 2 s.)
    const framesDrawn = () => page.evaluate(() => window.simDemo?.framesDrawn() ?? 0);
    await page.waitForTimeout(500); // the first frames and the map's first draw
    const idleFrom = await framesDrawn();
    await page.waitForTimeout(2000);
    expect((await framesDrawn()) - idleFrom).toBeLessThanOrEqual(4);

    // This Chromium draws WebGL in software (--disable-gpu: SwiftShader), so the page chose the
    // light render profile by itself, and said so.
    const render = await page.evaluate(() => window.simDemo?.render());
    expect(render?.name).toBe('light');
    expect(render?.rendererName).toMatch(/swiftshader/i);
    expect(render?.minFrameIntervalMs).toBeGreaterThan(0);
    await expect(page.locator('#status').textContent()).resolves.toMatch(
      /light rendering: WebGL drawn in software \(SwiftShader\)/i,
    );

    // Teleop: hold the up arrow, then let go; the robot has moved forward (+x) and stopped.
    const start = await page.evaluate(() => window.simDemo?.pose());
    await page.locator('#viewport > canvas').focus();
    const framesBeforeDrive = await framesDrawn();
    await page.keyboard.down('ArrowUp');
    await page.waitForFunction((x0) => (window.simDemo?.pose().x ?? 0) > x0 + 0.1, start?.x ?? 0, {
      timeout: 20_000,
    });
    await page.keyboard.up('ArrowUp');
    await page.waitForFunction(
      () => document.getElementById('status')?.textContent === 'Stopped',
      undefined,
      { timeout: 10_000 },
    );
    // While it moved, the view was drawn (the frame interval itself is FrameSchedule's unit test).
    expect((await framesDrawn()) - framesBeforeDrive).toBeGreaterThan(0);
    const afterTeleop = await page.evaluate(() => window.simDemo?.pose());
    expect(afterTeleop?.x ?? 0).toBeGreaterThan((start?.x ?? 0) + 0.1);
    expect(Math.abs(afterTeleop?.y ?? 1)).toBeLessThan(0.01);

    // "Plan around obstacles" off: one straight moveTo to a free point on the left.
    await page.locator('#plan-toggle').uncheck();
    const straight = { x: -1.5, y: 0.9 };
    await clickGoal(straight.x, straight.y);
    expect(await page.evaluate(() => window.simDemo?.goalState())).toBe('reached');
    let pose = await page.evaluate(() => window.simDemo?.pose());
    // The click lands within a few millimetres of the intended point on the floor.
    expect(Math.hypot((pose?.x ?? 0) - straight.x, (pose?.y ?? 0) - straight.y)).toBeLessThan(0.02);

    // On: the navigation bridge drives round the box to the far side of it, touching nothing.
    await page.locator('#plan-toggle').check();
    const behind = { x: -0.4, y: 0 };
    await clickGoal(behind.x, behind.y);
    expect(await page.evaluate(() => window.simDemo?.goalState())).toBe('reached');
    pose = await page.evaluate(() => window.simDemo?.pose());
    expect(Math.hypot((pose?.x ?? 0) - behind.x, (pose?.y ?? 0) - behind.y)).toBeLessThan(0.12);
    await expect(page.locator('#status').textContent()).resolves.toContain('Goal reached');
    await expect(page.locator('#log').textContent()).resolves.not.toContain('COLLISION');

    mkdirSync(artifacts, { recursive: true });
    await page.screenshot({ path: join(artifacts, 'sim-demo.png') });
    expect(problems).toEqual([]);
  }, 180_000); // typically 20-30 s alone; 75-90 s seen on a 2-core machine under full load
});
