// The demo's Perception toggle in a real browser (Debian's Chromium, driven by playwright-core):
// @hal/perception runs in the page on the robot's own camera frames (Three.js rendered, decoded
// by jpeg-js), finds the red box put in front of the robot, lists it where it stands, boxes it on
// the camera view, and draws the grid it perceives on the floor; off, all of that goes away.
// Saves a screenshot of the camera card to artifacts/demo-perception.png.
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { openDemoInChromium } from './demo-browser.js';
import type { DemoBrowser } from './demo-browser.js';

const artifacts = fileURLToPath(new URL('../../artifacts', import.meta.url));

interface PerceptionState {
  enabled: boolean;
  looks: number;
  objects: Array<{ label: string; bearingDeg: number; distanceM: number; x: number; y: number }>;
  cells: { free: number; occupied: number };
  error?: string;
}

interface DemoWindow {
  simDemo: {
    world: { setMap(map: unknown): void };
    pose(): { x: number; y: number; yaw: number };
    perception(): PerceptionState;
  };
}

/** The empty arena with a red box 0.9 m ahead of the start, a little to the left. */
const RED_BOX_MAP = {
  name: 'red box ahead',
  arena: { width: 5, height: 5 },
  obstacles: [
    { kind: 'box', x: 0.9, y: 0.15, width: 0.3, depth: 0.3, height: 0.3, color: '#d62828' },
  ],
  starts: [{ x: 0, y: 0, yaw: 0 }],
};

describe('apps/sim-demo: the Perception toggle in Chromium', () => {
  let demo: DemoBrowser;
  let page: Page;
  const state = () => page.evaluate(() => (window as unknown as DemoWindow).simDemo.perception());

  beforeAll(async () => {
    demo = await openDemoInChromium('sim-demo-perception');
    page = demo.page;
  }, 60_000);

  afterAll(async () => {
    await demo?.close();
  }, 30_000);

  it('lists the box the camera sees, boxes it on the camera view and maps the floor', async () => {
    await page.goto(`${demo.url}?map=empty`, { waitUntil: 'load', timeout: 20_000 });
    await page.waitForFunction(() => 'simDemo' in window, undefined, { timeout: 20_000 });
    await page.evaluate(
      (map) => (window as unknown as DemoWindow).simDemo.world.setMap(map),
      RED_BOX_MAP,
    );
    expect((await state()).enabled).toBe(false);

    await page.locator('#perception-toggle').check();
    await page.waitForFunction(
      () =>
        (window as unknown as DemoWindow).simDemo
          .perception()
          .objects.some((o) => o.label.startsWith('red')),
      undefined,
      { timeout: 30_000 },
    );
    const seen = await state();
    expect(seen.error).toBeUndefined();
    const red = seen.objects.find((o) => o.label.startsWith('red'));
    // the box's centre, where the map has it (the Three.js frames are not the software
    // renderer's: held to 15 cm)
    expect(Math.hypot((red?.x ?? 0) - 0.9, (red?.y ?? 0) - 0.15)).toBeLessThan(0.15);
    expect(red?.bearingDeg).toBeGreaterThan(0);
    await expect(page.locator('#perception-list').textContent()).resolves.toMatch(
      /red (box|pillar|object)?.*m, at \(0\.\d\d, 0\.\d\d\)/,
    );

    // the camera overlay has the box's red outline drawn on it
    const redPixels = await page.evaluate(() => {
      const canvas = document.getElementById('camera-overlay') as HTMLCanvasElement;
      const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
      let count = 0;
      for (let i = 0; i < data.length; i += 4) {
        if (data[i + 3]! > 200 && data[i]! > 200 && data[i + 1]! < 80 && data[i + 2]! < 80)
          count += 1;
      }
      return count;
    });
    expect(redPixels).toBeGreaterThan(50);

    // the perceived grid: free floor in front of the robot, the box's face occupied
    await page.waitForFunction(
      () => {
        const { cells } = (window as unknown as DemoWindow).simDemo.perception();
        return cells.free > 50 && cells.occupied > 0;
      },
      undefined,
      { timeout: 20_000 },
    );

    mkdirSync(artifacts, { recursive: true });
    await page
      .locator('.camera-frame')
      .screenshot({ path: `${artifacts}/demo-perception.png`, timeout: 10_000 });

    await page.locator('#perception-toggle').uncheck();
    await page.waitForFunction(
      () => !(window as unknown as DemoWindow).simDemo.perception().enabled,
      undefined,
      { timeout: 5_000 },
    );
    await expect(page.locator('#perception-list li').count()).resolves.toBe(0);
    expect(demo.problems).toStrictEqual([]);
  }, 90_000);
});
