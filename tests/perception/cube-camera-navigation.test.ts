// The camera-only navigation agent on the V1 cube, over the real wire: `hal emulate --camera` runs
// the firmware's cube-emulator and serves the ESP32-CAM's MJPEG stream rendered from the emulated
// body's true pose in a world file; the eval's nav-camera agent drives a PhysicalHAL over UDP,
// mapping what the frames show into the navigation bridge's grid, and stops before the box it was
// told of. The cube has no range sensors: the camera is all it has.
import { cameraNavigationAgent } from '@hal/eval';
import type { NavigationBridge } from '@hal/navigation';
import type { PhysicalHAL } from '@hal/physical';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulatedCube } from '../helpers/emulated-cube.js';
import type { EmulatedCube } from '../helpers/emulated-cube.js';
import { WALL_AND_BOX_WORLD } from './wall-and-box.fixture.js';

let cube: EmulatedCube;
let hal: PhysicalHAL;

beforeAll(async () => {
  cube = await startEmulatedCube({ world: WALL_AND_BOX_WORLD, timeScale: 10 });
  hal = cube.physicalHal({ freshCaptures: true });
  await hal.initialize();
}, 60_000);

afterAll(async () => {
  await hal?.cleanup();
  await cube?.dispose();
});

/** Distance from (x, y) to the 0.3 m box at (0.7, 0.25), metres. */
function toBox(x: number, y: number): number {
  return Math.hypot(Math.max(Math.abs(x - 0.7) - 0.15, 0), Math.max(Math.abs(y - 0.25) - 0.15, 0));
}

describe('the V1 cube finds a box with its camera alone', { timeout: 60_000 }, () => {
  it('maps the wall it sees and stops within 25 cm of the box it was told of', async () => {
    let bridge: NavigationBridge | undefined;
    const agent = cameraNavigationAgent({ onBridge: (b) => (bridge = b) });
    const controller = new AbortController();
    const answer = await agent.run({
      instruction: 'Drive to the yellow box and stop within 25 cm of it.',
      tools: [],
      execute: () => Promise.reject(new Error('the agent drives the HAL, not the tools')),
      signal: controller.signal,
      maxToolCalls: 100,
      hal,
    });
    expect(answer.stopped, answer.answer).toBeUndefined();
    expect(answer.answer).toMatch(/^Stopped next to the yellow box/);
    // The cube's own odometry (the emulator moves it exactly as told): beside the box, not in it.
    const { position } = await hal.locomotion.getPose();
    const away = toBox(position.x, position.y);
    expect(Math.hypot(position.x, position.y)).toBeGreaterThan(0.2);
    expect(away).toBeLessThanOrEqual(0.25);
    expect(away).toBeGreaterThan(0.05);
    // What the frames showed is in the bridge's grid: the wall beyond, free floor before it.
    expect(bridge?.grid.stateAt(1.18, -0.4)).toBe('occupied');
    expect(bridge?.grid.stateAt(0.5, -0.3)).toBe('free');
  });
});
