// The cube's camera path over the real wire (docs/cli.md, hal emulate --camera): `hal emulate` as a
// process runs the firmware's cube-emulator and serves the ESP32-CAM's interface; this process
// drives the robot with a PhysicalHAL over UDP and reads frames over HTTP (MJPEG), as it would a
// real cube. Each frame must show the world file as the simulator's camera renders it from the
// robot's true pose: the same red box, the same size, in the same columns.
import { parseWorldFile, realiseWorld } from '@hal/eval';
import type { PhysicalHAL } from '@hal/physical';
import { renderRobotView, SimRobot, World } from '@hal/simulation';
import type { RgbaImage } from '@hal/simulation';
import jpeg from 'jpeg-js';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulatedCube } from '../helpers/emulated-cube.js';
import type { EmulatedCube } from '../helpers/emulated-cube.js';

const TOKEN = 'camera-e2e-token';
const TIME_SCALE = 10;
/** A red box ahead and a blue pillar to the right of where the robot will face after a turn. */
const WORLD_TEXT = JSON.stringify({
  map: 'empty',
  start: { x: -0.5, y: 0, yawDeg: 0 },
  objects: [
    { name: 'red-box', kind: 'box', colour: 'red', x: 0.6, y: 0.15 },
    { name: 'blue-pillar', kind: 'cylinder', colour: 'blue', x: 0.4, y: -0.6 },
  ],
});
const WORLD = realiseWorld(parseWorldFile(WORLD_TEXT, 'world.json'));

/** The red of the red box (#d62828, shaded): count and mean column. */
function red(image: RgbaImage): { count: number; column: number } {
  let count = 0;
  let columns = 0;
  for (let i = 0; i < image.width * image.height; i += 1) {
    const [r, g, b] = [image.data[i * 4]!, image.data[i * 4 + 1]!, image.data[i * 4 + 2]!];
    if (r > 110 && g * 2 < r && b * 2 < r) {
      count += 1;
      columns += i % image.width;
    }
  }
  return { count, column: columns / count };
}

/** What the simulator's camera shows from `pose` in the world. */
function expected(pose: { x: number; y: number; yaw: number }) {
  return red(
    renderRobotView(new World({ map: WORLD.map }), new SimRobot({ id: 'truth', start: pose })),
  );
}

function decode(dataUrl: string): RgbaImage {
  const bytes = Buffer.from(dataUrl.replace(/^data:image\/jpeg;base64,/, ''), 'base64');
  const image = jpeg.decode(bytes, { useTArray: true });
  return { width: image.width, height: image.height, data: image.data };
}

let cube: EmulatedCube;
let hal: PhysicalHAL;
let cameraUrl: string;

beforeAll(async () => {
  cube = await startEmulatedCube({
    world: JSON.parse(WORLD_TEXT),
    timeScale: TIME_SCALE,
    token: TOKEN,
  });
  cameraUrl = cube.cameraUrl;
  hal = cube.physicalHal();
  await hal.initialize();
}, 60_000);

afterAll(async () => {
  await hal?.cleanup();
  await cube?.dispose();
});

/** A frame made after the last motion ended (three more frames sent: bounded, 5 s). */
async function frameNow(): Promise<RgbaImage> {
  await cube.freshFrames();
  return decode(await hal.vision.captureFrame());
}

describe('hal emulate --camera, over UDP and MJPEG', { timeout: 60_000 }, () => {
  it("shows the world file from the robot's true pose as it drives and turns", async () => {
    const start = await frameNow();
    expect([start.width, start.height]).toEqual([320, 240]);
    const seen: { what: string; got: ReturnType<typeof red>; want: ReturnType<typeof red> }[] = [];
    seen.push({ what: 'start', got: red(start), want: expected(WORLD.start) });

    // the truth is where the commands put the body (to a step, 1/217 cm), not what it reported
    expect(await hal.locomotion.moveForward(40)).toMatchObject({ success: true });
    const ahead = { ...WORLD.start, x: WORLD.start.x + 0.4 };
    seen.push({ what: 'forward 40 cm', got: red(await frameNow()), want: expected(ahead) });

    expect(await hal.locomotion.rotate('left', 15)).toMatchObject({ success: true });
    const turned = { ...ahead, yaw: (15 * Math.PI) / 180 };
    seen.push({ what: 'left 15 deg', got: red(await frameNow()), want: expected(turned) });

    for (const { what, got, want } of seen) {
      expect(want.count, what).toBeGreaterThan(200);
      // JPEG blurs the box's edges a little; its size and place are the truth's
      expect(Math.abs(got.count - want.count) / want.count, what).toBeLessThan(0.05);
      expect(Math.abs(got.column - want.column), what).toBeLessThan(2);
    }
    // and the camera saw the motion: the box grew ahead, then moved right as the robot turned left
    const [a, b, c] = seen.map((s) => s.got);
    expect(b!.count).toBeGreaterThan(a!.count * 1.5);
    expect(c!.column).toBeGreaterThan(b!.column + 20);
  });

  it('asks for the token, as the camera sketch does, and reports its status', async () => {
    const refused = await fetch(`${cameraUrl}/stream`);
    expect(refused.status).toBe(401);
    expect(refused.headers.get('www-authenticate')).toBe('Bearer realm="cube-camera"');
    await refused.body?.cancel();
    const status = await fetch(`${cameraUrl}/status?token=${TOKEN}`);
    expect(status.status).toBe(200);
    const body = (await status.json()) as Record<string, number>;
    expect(body).toMatchObject({ width: 320, height: 240, stream_clients: 1 });
    expect(body['frames_served']).toBeGreaterThan(0);
    expect(body['fps']).toBeGreaterThan(0);
  });
});
