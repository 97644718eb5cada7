// `hal look` on the cube's path (docs/perception.md): `hal emulate --camera --world FILE` as a
// process runs the firmware's cube-emulator and serves the ESP32-CAM's interface; `hal look --udp
// ... --camera-url ...`, another process, reads the pose over UDP and a frame over MJPEG, as it
// would from a real cube, and finds the world's objects where the file puts them.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { LookDocumentSchema } from '@hal/cli';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { runHalProcess, startHalProcess, stopAllHal } from '../helpers/hal-process.js';
import { EMULATOR_PATH, requireEmulator } from '../physical/emulator.js';

type Line = Record<string, unknown> & { event: string };

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

let dir: string;
let udp: string;
let cameraUrl: string;

beforeAll(async () => {
  requireEmulator();
  dir = await mkdtemp(join(tmpdir(), 'hal-look-emulated-'));
  const file = join(dir, 'world.json');
  await writeFile(file, JSON.stringify(WORLD));
  const emulate = startHalProcess<Line>([
    '--json',
    'emulate',
    '--emulator',
    EMULATOR_PATH,
    '--udp-port',
    '0',
    '--no-pty',
    '--no-announce',
    '--camera',
    '0',
    '--camera-token',
    TOKEN,
    '--world',
    file,
  ]);
  const ready = await emulate.waitFor((l) => l.event === 'ready');
  udp = `127.0.0.1:${String(ready['udpPort'])}`;
  cameraUrl = (ready['camera'] as { url: string }).url;
}, 60_000);

afterAll(async () => {
  await stopAllHal();
  if (dir !== undefined) await rm(dir, { recursive: true, force: true });
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
