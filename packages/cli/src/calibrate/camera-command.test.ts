// `hal calibrate camera` end to end: the emulated cube (`hal emulate --camera`, whose camera
// renders a world file with V1's camera model: 20 degrees down, 9 cm up) reached over UDP and its
// MJPEG camera, a red box straight ahead; the fitted tilt comes back as 20 degrees and is saved
// beside the wheels, and the next connection to the robot reports it.
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Command } from 'commander';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import type { CapturedIO } from '../testing/capture-io.js';
import { builtEmulatorPath } from '../emulate/emulator-path.fixture.js';
import { runHal } from '../program.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { openTarget } from '../target-hal.js';

/** A red box 30 cm deep whose near face is 85 cm straight ahead of the start. */
const WORLD = {
  map: 'empty',
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [{ name: 'target', kind: 'box', colour: 'red', x: 1, y: 0, width: 0.3, depth: 0.3 }],
};

let dir: string;
let worldFile: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-calibrate-camera-'));
  worldFile = join(dir, 'world.json');
  await writeFile(worldFile, JSON.stringify(WORLD));
});
afterAll(() => rm(dir, { recursive: true, force: true }));

const running: { io: CapturedIO; done: Promise<number> }[] = [];
afterEach(async () => {
  for (const run of running.splice(0)) {
    run.io.abort();
    await run.done;
  }
});

/** `hal emulate --camera` with the world file: its UDP port, camera URL and device id. */
async function emulateWithCamera() {
  const io = captureIO();
  const done = runHal(
    ['--json', 'emulate', '--emulator', builtEmulatorPath(), '--udp-port', '0', '--no-pty'].concat([
      '--no-announce',
      '--time-scale',
      '10',
      // 1 s of real time at this clock: a heartbeat held back on a loaded machine stops no motion
      '--host-timeout-ms',
      '10000',
      '--camera',
      '0',
      '--world',
      worldFile,
    ]),
    io,
  );
  running.push({ io, done });
  const deadline = Date.now() + 15_000;
  while (Date.now() < deadline) {
    const lines = io.stdout() === '' ? [] : (io.jsonLines() as Record<string, unknown>[]);
    const ready = lines.find((l) => l['event'] === 'ready');
    if (ready !== undefined) {
      return ready as { udpPort: number; deviceId: string; camera: { url: string } };
    }
    if ((await Promise.race([done, Promise.resolve(undefined)])) !== undefined) break;
    await new Promise((resolve) => setTimeout(resolve, 25));
  }
  throw new Error(`not ready; stdout: ${io.stdout()} stderr: ${io.stderr()}`);
}

interface CameraDoc {
  deviceId: string;
  before: { tiltDeg: number; heightM: number };
  after: { tiltDeg: number; heightM: number };
  fittedHeight: boolean;
  residualM: number;
  sightings: Array<{ distanceM: number; row: number; predictedM: number }>;
  file?: string;
}

describe('hal calibrate camera', { timeout: 40_000 }, () => {
  it('gets the emulated camera’s 20 degrees back from a red box at 85 cm, saves it, and the robot reports it next time', async () => {
    const ready = await emulateWithCamera();
    const calibrationDir = join(dir, 'calibration');
    const env = { HAL_CALIBRATION_DIR: calibrationDir };
    const robot = ['--udp', `127.0.0.1:${ready.udpPort}`, '--time-scale', '10'];
    const camera = ['--camera-url', ready.camera.url];
    // a wheel calibration first: the camera's is saved beside it
    const wheels = captureIO(env);
    const wheelArgs = ['--measured-distance-cm', '100', '--measured-turn-deg', '360'];
    expect(
      await runHal(['--json', 'calibrate', ...robot, ...wheelArgs], wheels),
      wheels.stderr(),
    ).toBe(0);

    const io = captureIO(env);
    const code = await runHal(
      ['--json', 'calibrate', 'camera', ...robot, ...camera, '--distance', '85cm', '--frames', '3'],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const doc = io.jsonLines()[0] as CameraDoc;
    expect(doc.before).toMatchObject({ tiltDeg: 20, heightM: 0.09 });
    expect(Math.abs(doc.after.tiltDeg - 20)).toBeLessThan(0.5);
    expect(doc.after.heightM).toBe(0.09);
    expect(doc.fittedHeight).toBe(false);
    expect(doc.residualM).toBeLessThan(0.001);
    expect(doc.sightings).toHaveLength(1);
    expect(doc.file).toBe(join(calibrationDir, `${doc.deviceId}.json`));

    const saved = JSON.parse(await readFile(doc.file!, 'utf8')) as Record<string, unknown>;
    expect(saved).toMatchObject({
      version: 1,
      deviceId: doc.deviceId,
      wheelDiameterCm: expect.closeTo(6, 2),
      camera: {
        model: doc.after,
        measurements: [{ colour: 'red', distanceM: 0.85, baseRow: doc.sightings[0]!.row }],
      },
    });

    // a later connection loads the camera with the wheels, and reports it
    const command = addTargetOptions(new Command('x').exitOverride());
    command.parse([...robot, ...camera], { from: 'user' });
    const target = resolveTarget(command.opts<TargetCliOptions>(), env);
    const opened = await openTarget(target, captureIO(env));
    try {
      expect(opened.hal.getDeviceInfo().camera).toEqual(doc.after);
    } finally {
      await opened.close();
    }

    // a wheel calibration after it keeps the camera's
    const again = captureIO(env);
    expect(
      await runHal(['--json', 'calibrate', ...robot, ...wheelArgs], again),
      again.stderr(),
    ).toBe(0);
    const kept = JSON.parse(await readFile(doc.file!, 'utf8')) as Record<string, unknown>;
    expect(kept['camera']).toEqual(saved['camera']);
  });

  it('refuses a robot with no camera, a distance out of range, and a target too near for its base to be in view', async () => {
    const ready = await emulateWithCamera();
    const robot = ['--udp', `127.0.0.1:${ready.udpPort}`, '--time-scale', '10'];
    const env = { HAL_CALIBRATION_DIR: join(dir, 'none') };
    const blind = captureIO(env);
    expect(await runHal(['calibrate', 'camera', ...robot, '--distance', '85cm'], blind)).toBe(2);
    expect(blind.stderr()).toContain('the robot has no camera to calibrate: give its ESP32-CAM');

    const wrong = captureIO(env);
    const args = ['calibrate', 'camera', ...robot, '--camera-url', ready.camera.url];
    expect(await runHal([...args, '--distance', '5cm'], wrong)).toBe(2);
    expect(wrong.stderr()).toContain('"--distance" must be a distance in 0.1..5 m, got "5cm"');

    // the robot drives up to the box: its base goes below the image's bottom edge
    const command = addTargetOptions(new Command('x').exitOverride());
    command.parse([...robot, '--camera-url', ready.camera.url], { from: 'user' });
    const opened = await openTarget(
      resolveTarget(command.opts<TargetCliOptions>(), env),
      captureIO(env),
    );
    try {
      const moved = await opened.hal.locomotion.moveForward(75);
      expect(moved.success, moved.error).toBe(true);
    } finally {
      await opened.close();
    }
    const near = captureIO(env);
    expect(await runHal([...args, '--distance', '10cm', '--frames', '2'], near)).toBe(1);
    expect(near.stderr()).toContain(
      'the red target is cut by the bottom of the image, so its base is out of view: move it farther away',
    );
  });

  it('needs a --distance, and a terminal for more than one', async () => {
    const io = captureIO();
    expect(await runHal(['calibrate', 'camera', '--udp', '127.0.0.1:9'], io)).toBe(2);
    expect(io.stderr()).toContain('give --distance');
    const two = captureIO();
    const args = ['calibrate', 'camera', '--udp', '127.0.0.1:9', '--distance', '40cm'];
    expect(await runHal([...args, '--distance', '80cm'], two)).toBe(2);
    expect(two.stderr()).toContain('two or more --distance values need a terminal');
  });
});
