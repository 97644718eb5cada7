// The V1 cube maps what it sees, over the real wire: `hal emulate --camera` runs the firmware's
// cube-emulator and serves the ESP32-CAM's MJPEG stream rendered from the emulated body's true
// pose in a world file; a PhysicalHAL drives it over UDP and perception looks through
// captureFrame and getPose only, as it would on the desk.
import { OccupancyGrid } from '@hal/navigation';
import { Perception } from '@hal/perception';
import type { PhysicalHAL } from '@hal/physical';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulatedCube } from '../helpers/emulated-cube.js';
import type { EmulatedCube } from '../helpers/emulated-cube.js';
import { WALL_AND_BOX_WORLD } from './wall-and-box.fixture.js';

let cube: EmulatedCube;
let hal: PhysicalHAL;

beforeAll(async () => {
  cube = await startEmulatedCube({ world: WALL_AND_BOX_WORLD, timeScale: 10 });
  hal = cube.physicalHal();
  await hal.initialize();
}, 60_000);

afterAll(async () => {
  await hal?.cleanup();
  await cube?.dispose();
});

describe('the V1 cube sees through its camera', { timeout: 60_000 }, () => {
  it('finds the box and maps the wall, then still after driving towards them', async () => {
    const grid = new OccupancyGrid({ widthM: 6, heightM: 6, resolutionM: 0.05 });
    const perception = new Perception(hal, { grid });
    await cube.freshFrames();
    const first = await perception.look();
    expect(first.objects.map((o) => o.label)).toEqual(['yellow box']);
    const box = first.objects[0];
    expect(Math.hypot((box?.world.x ?? 0) - 0.7, (box?.world.y ?? 0) - 0.25)).toBeLessThan(0.06);
    expect(grid.stateAt(0.5, -0.3)).toBe('free');
    expect(grid.stateAt(1.18, -0.4)).toBe('occupied');
    expect(grid.stateAt(1.5, -0.4)).toBe('unknown');

    // Drive 30 cm; the odometry moves the believed pose, the camera the view: they agree.
    expect((await hal.locomotion.moveForward(30)).success).toBe(true);
    await cube.freshFrames();
    const second = await perception.look();
    expect(second.pose.x).toBeCloseTo(0.3, 2);
    const [remembered] = perception.where('yellow box');
    expect(remembered?.timesSeen).toBe(2);
    expect(Math.hypot((remembered?.x ?? 0) - 0.7, (remembered?.y ?? 0) - 0.25)).toBeLessThan(0.06);
    // Now seen nearer: the wall to the right (the box hides it on the left).
    expect(grid.stateAt(1.18, -0.35)).toBe('occupied');
    expect(grid.stateAt(1.0, -0.35)).toBe('free');
  });
});
