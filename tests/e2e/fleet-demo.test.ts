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

interface FleetState {
  mode: string;
  busy: boolean;
  lastReport: {
    success: boolean;
    results: Array<{ device: string; success: boolean; code?: string }>;
  } | null;
  formation: { running: boolean; leader: string; shape: string } | null;
  formationEnd: string | null;
  estopped: boolean;
}

interface FleetDemoHooks {
  robotId: string;
  robots(): RobotView[];
  fleet(): FleetState;
  slotErrors(): Array<{ device: string; errorM: number }>;
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

  it("runs the fleet modes: one command to all with each robot's own result, a formation behind the leader, the fleet e-stop", async () => {
    // Every robot back at a free place, facing +x.
    await page.locator('#reset-button').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.robots().every((r) => !r.running),
      undefined,
      { timeout: 10_000 },
    );

    // Synchronized, with R3's own e-stop latched: R3 alone fails, with its own code.
    await page.locator('.robot-item[data-robot-id="robot-3"]').click();
    await page.locator('#estop-button').click();
    await page.locator('#fleet-mode').selectOption('synchronized');
    await page.locator('#fleet-command').selectOption('forward');
    await page.locator('#fleet-amount').fill('20');
    const before = await robots();
    await page.locator('#fleet-send').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.fleet().lastReport !== null,
      undefined,
      { timeout: 60_000 },
    );
    const report = (await page.evaluate(() => (window as unknown as DemoWindow).simDemo.fleet()))
      .lastReport;
    expect(report?.success).toBe(false);
    expect(report?.results.map((r) => [r.device, r.success, r.code])).toEqual([
      ['robot-1', true, undefined],
      ['robot-2', true, undefined],
      ['robot-3', false, 'EMERGENCY_STOPPED'],
      ['robot-4', true, undefined],
    ]);
    await expect(page.locator('#fleet-results li.fail').textContent()).resolves.toContain(
      'R3 ✗ EMERGENCY_STOPPED',
    );
    const after = await robots();
    after.forEach((robot, i) => {
      const moved = robot.x - (before[i]?.x ?? 0);
      // 20 cm ahead (+x), to a few millimetres (whole steps); R3 did not move.
      expect(moved).toBeCloseTo(robot.id === 'robot-3' ? 0 : 0.2, 2);
    });
    await page.locator('#estop-button').click(); // resets R3's e-stop

    // Leader-follower: R1 leads a wedge; the others gather in their slots, then follow it.
    await page.locator('.robot-item[data-robot-id="robot-1"]').click();
    await page.locator('#fleet-mode').selectOption('leader-follower');
    await page.locator('#formation-shape').selectOption('wedge');
    await page.locator('#formation-toggle').click();
    const inSlots = () => {
      const errors = (window as unknown as DemoWindow).simDemo.slotErrors();
      return errors.length === 3 && errors.every((e) => e.errorM < 0.06);
    };
    await page.waitForFunction(inSlots, undefined, { timeout: 90_000 });
    const start = (await robots())[0];
    await page.locator('#viewport > canvas').focus();
    await page.keyboard.down('ArrowUp');
    await page.waitForFunction(
      (x0) => ((window as unknown as DemoWindow).simDemo.robots()[0]?.x ?? 0) > x0 + 0.4,
      start?.x ?? 0,
      { timeout: 30_000 },
    );
    await page.keyboard.up('ArrowUp');
    await page.waitForFunction(inSlots, undefined, { timeout: 90_000 });
    const state = await page.evaluate(() => (window as unknown as DemoWindow).simDemo.fleet());
    expect(state.formation).toEqual({ running: true, leader: 'robot-1', shape: 'wedge' });

    // The fleet e-stop latches every robot and ends the formation; its reset clears them all.
    await page.locator('#fleet-estop').click();
    await page.waitForFunction(
      () => (window as unknown as DemoWindow).simDemo.fleet().formationEnd === 'estop',
      undefined,
      { timeout: 20_000 },
    );
    expect((await robots()).map((r) => r.emergencyStopped)).toEqual([true, true, true, true]);
    await expect(page.locator('#fleet-estop').textContent()).resolves.toBe('RESET FLEET E-STOP');
    await page.locator('#fleet-estop').click();
    await page.waitForFunction(
      () => !(window as unknown as DemoWindow).simDemo.fleet().estopped,
      undefined,
      { timeout: 20_000 },
    );
    expect((await robots()).map((r) => r.emergencyStopped)).toEqual([false, false, false, false]);

    mkdirSync(artifacts, { recursive: true });
    await page.screenshot({ path: join(artifacts, 'fleet-demo.png') });
    expect(demo.problems).toEqual([]);
  }, 300_000);
});
