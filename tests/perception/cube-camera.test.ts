// The V1 cube maps what it sees, over the real wire: `hal emulate --camera` runs the firmware's
// cube-emulator and serves the ESP32-CAM's MJPEG stream rendered from the emulated body's true
// pose in a world file; a PhysicalHAL drives it over UDP and perception looks through
// captureFrame and getPose only, as it would on the desk.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { OccupancyGrid } from '@hal/navigation';
import { Perception } from '@hal/perception';
import { PhysicalHAL } from '@hal/physical';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startHalProcess, stopAllHal } from '../helpers/hal-process.js';
import { EMULATOR_PATH, requireEmulator } from '../physical/emulator.js';

type Line = Record<string, unknown> & { event: string };

const TIME_SCALE = 10;
/** The robot starts at the origin facing +x: a yellow box ahead-left, a wall 1.2 m ahead. */
const WORLD_TEXT = JSON.stringify({
  map: {
    name: 'a wall ahead',
    arena: { width: 6, height: 6 },
    walls: [{ from: [1.2, -1.5], to: [1.2, 1.5], thickness: 0.06 }],
  },
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [{ name: 'target', kind: 'box', colour: 'yellow', x: 0.7, y: 0.25 }],
});

let dir: string;
let hal: PhysicalHAL;
let cameraUrl: string;

beforeAll(async () => {
  requireEmulator();
  dir = await mkdtemp(join(tmpdir(), 'hal-cube-camera-'));
  const file = join(dir, 'world.json');
  await writeFile(file, WORLD_TEXT);
  const emulate = startHalProcess<Line>([
    '--json',
    'emulate',
    '--emulator',
    EMULATOR_PATH,
    '--udp-port',
    '0',
    '--no-pty',
    '--no-announce',
    '--time-scale',
    String(TIME_SCALE),
    '--camera',
    '0',
    '--world',
    file,
  ]);
  const ready = await emulate.waitFor((l) => l.event === 'ready');
  cameraUrl = (ready['camera'] as { url: string }).url;
  hal = new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: 'cube',
      connection: {
        type: 'wifi',
        host: '127.0.0.1',
        udpPort: ready['udpPort'] as number,
        cameraUrl,
      },
    },
    { timeScale: TIME_SCALE },
  );
  await hal.initialize();
}, 60_000);

afterAll(async () => {
  await hal?.cleanup();
  await stopAllHal();
  if (dir !== undefined) await rm(dir, { recursive: true, force: true });
});

/** Waits until the camera has sent three frames more (each is rendered as it is sent). */
async function freshFrames(): Promise<void> {
  const served = async () =>
    ((await (await fetch(`${cameraUrl}/status`)).json()) as { frames_served: number })
      .frames_served;
  const target = (await served()) + 3;
  const deadline = Date.now() + 5000;
  while ((await served()) < target) {
    if (Date.now() > deadline) throw new Error('the camera sent no new frames in 5 s');
    await new Promise((resolve) => setTimeout(resolve, 30));
  }
}

describe('the V1 cube sees through its camera', { timeout: 60_000 }, () => {
  it('finds the box and maps the wall, then still after driving towards them', async () => {
    const grid = new OccupancyGrid({ widthM: 6, heightM: 6, resolutionM: 0.05 });
    const perception = new Perception(hal, { grid });
    await freshFrames();
    const first = await perception.look();
    expect(first.objects.map((o) => o.label)).toEqual(['yellow box']);
    const box = first.objects[0];
    expect(Math.hypot((box?.world.x ?? 0) - 0.7, (box?.world.y ?? 0) - 0.25)).toBeLessThan(0.06);
    expect(grid.stateAt(0.5, -0.3)).toBe('free');
    expect(grid.stateAt(1.18, -0.4)).toBe('occupied');
    expect(grid.stateAt(1.5, -0.4)).toBe('unknown');

    // Drive 30 cm; the odometry moves the believed pose, the camera the view: they agree.
    expect((await hal.locomotion.moveForward(30)).success).toBe(true);
    await freshFrames();
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
