// `hal look` on the cube's path (docs/perception.md): `hal emulate --camera --world FILE` as a
// process runs the firmware's cube-emulator and serves the ESP32-CAM's interface; `hal look --udp
// ... --camera-url ...`, another process, reads the pose over UDP and a frame over MJPEG, as it
// would from a real cube, and finds the world's objects where the file puts them.
import { LookDocumentSchema } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startEmulatedCube } from '../helpers/emulated-cube.js';
import type { EmulatedCube } from '../helpers/emulated-cube.js';
import { runHalProcess } from '../helpers/hal-process.js';

const TOKEN = 'look-e2e-token';
/** The robot starts at (-0.5, 0) facing +x: a red box ahead and left, a blue pillar right. */
const WORLD = {
  map: 'empty',
  start: { x: -0.5, y: 0, yawDeg: 0 },
  objects: [
    { name: 'red-box', kind: 'box', colour: 'red', x: 0.5, y: 0.2 },
    { name: 'blue-pillar', kind: 'cylinder', colour: 'blue', x: 0.7, y: -0.45 },
  ],
};

let cube: EmulatedCube;
let udp: string;
let cameraUrl: string;

beforeAll(async () => {
  cube = await startEmulatedCube({ world: WORLD, token: TOKEN });
  udp = `127.0.0.1:${String(cube.udpPort)}`;
  cameraUrl = cube.cameraUrl;
}, 60_000);

afterAll(async () => {
  await cube?.dispose();
});

describe('hal look --udp --camera-url, on the emulated cube', () => {
  it('lists the objects in view, placed in the odometry frame (which starts at the cube)', async () => {
    const run = await runHalProcess(
      ['look', '--udp', udp, '--camera-url', cameraUrl, '--camera-token', TOKEN, '--json'],
      60_000,
    );
    expect(run.code, run.stderr).toBe(0);
    const doc = LookDocumentSchema.parse(JSON.parse(run.stdout));
    expect(doc.robot).toBe(`robot at udp ${udp}`);
    expect(doc.pose).toStrictEqual({ xM: 0, yM: 0, yawDeg: 0 });
    // the odometry frame starts where the cube was switched on: the world's start
    for (const object of WORLD.objects) {
      const seen = doc.objects.find((o) => o.colour === object.colour);
      expect(seen, object.name).toBeDefined();
      const x = object.x - WORLD.start.x;
      const y = object.y - WORLD.start.y;
      const error = Math.hypot((seen?.world.xM ?? 0) - x, (seen?.world.yM ?? 0) - y);
      expect(error, `${object.name} at ${JSON.stringify(seen?.world)}`).toBeLessThan(0.1);
    }
  });

  it('refuses a cube whose camera it was not given, by name, and says how to give it', async () => {
    const run = await runHalProcess(['look', '--udp', udp], 60_000);
    expect(run.code).toBe(1);
    expect(run.stderr).toMatch(
      new RegExp(
        `^hal: NOT_IMPLEMENTED: the robot at udp ${udp.replace(/\./g, '\\.')} \\(.+\\) has no camera: it cannot look \\(give its ESP32-CAM with --camera-url`,
        'm',
      ),
    );
  });
});
