// `hal emulate --camera` in-process with the real cube-emulator: the camera it serves, reached
// as every command reaches a robot's camera (--udp with --camera-url and the token from
// $HAL_CAMERA_TOKEN), sees the world file from where the emulated body is.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import type { AddressInfo } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { Command } from 'commander';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { captureIO } from '../testing/capture-io.js';
import type { CapturedIO } from '../testing/capture-io.js';
import { builtEmulatorPath } from '../emulate/emulator-path.fixture.js';
import { redRegion } from '../emulate/frame-colour.fixture.js';
import { framesLater } from '../emulate/served-frames.fixture.js';
import { runHal } from '../program.js';
import { addTargetOptions, resolveTarget } from '../target.js';
import type { TargetCliOptions } from '../target.js';
import { openTarget } from '../target-hal.js';

const TOKEN = 'emulated-cam-token';
/** A red box 1 m straight ahead of the start. */
const WORLD = {
  map: 'empty',
  start: { x: 0, y: 0, yawDeg: 0 },
  objects: [{ name: 'red-box', kind: 'box', colour: 'red', x: 1, y: 0 }],
};

let dir: string;
let worldFile: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-emulate-camera-'));
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

async function emulateWithCamera(args: string[], env: Record<string, string> = {}) {
  const io = captureIO(env);
  const done = runHal(
    ['--json', 'emulate', '--emulator', builtEmulatorPath(), '--udp-port', '0', '--no-pty'].concat([
      '--no-announce',
      '--time-scale',
      '10',
      // the longest host timeout: at 10x the 2 s default is 200 ms of real time, which this
      // process (rendering the frames and driving the robot) can miss on a loaded machine
      '--host-timeout-ms',
      '10000',
      '--camera',
      '0',
      ...args,
    ]),
    io,
  );
  running.push({ io, done });
  const deadline = Date.now() + 15_000;
  while (Date.now() < deadline) {
    const lines = io.stdout() === '' ? [] : (io.jsonLines() as Record<string, unknown>[]);
    const ready = lines.find((l) => l['event'] === 'ready');
    if (ready !== undefined) return ready as { udpPort: number; camera: { url: string } };
    if ((await Promise.race([done, Promise.resolve(undefined)])) !== undefined) break;
    await new Promise((resolve) => setTimeout(resolve, 25));
  }
  throw new Error(`not ready; stdout: ${io.stdout()} stderr: ${io.stderr()}`);
}

/** The robot as a command names it on its command line. */
function targetOf(argv: string[], env: Record<string, string>) {
  const command = addTargetOptions(new Command('x').exitOverride());
  command.parse(argv, { from: 'user' });
  return resolveTarget(command.opts<TargetCliOptions>(), env);
}

describe('hal emulate --camera', { timeout: 30_000 }, () => {
  it('serves frames of the world file that follow the emulated robot, behind its token', async () => {
    const ready = await emulateWithCamera(['--world', worldFile], { HAL_CAMERA_TOKEN: TOKEN });
    const url = ready.camera.url;
    expect(ready.camera).toEqual({ url, world: worldFile, token: true });

    expect((await fetch(`${url}/stream`)).status).toBe(401);
    const status = await fetch(`${url}/status`, { headers: { Authorization: `Bearer ${TOKEN}` } });
    expect(await status.json()).toMatchObject({ width: 320, height: 240, rssi_dbm: 0 });

    const env = { HAL_CAMERA_TOKEN: TOKEN };
    const target = targetOf(
      ['--udp', `127.0.0.1:${ready.udpPort}`, '--time-scale', '10', '--camera-url', url],
      env,
    );
    const opened = await openTarget(target, captureIO(env));
    try {
      // a frame is rendered as it is sent: a few sent after now show the robot as it is now
      const settle = () => framesLater(url, TOKEN);
      await settle();
      const before = redRegion(await opened.hal.vision.captureFrame());
      expect([before.width, before.height]).toEqual([320, 240]);
      expect(before.count).toBeGreaterThan(100);
      expect(Math.abs(before.column - 160)).toBeLessThan(10); // straight ahead

      const moved = await opened.hal.locomotion.moveForward(50);
      expect(moved.success, moved.error).toBe(true);
      await settle();
      const after = redRegion(await opened.hal.vision.captureFrame());
      expect(after.count).toBeGreaterThan(before.count * 2);
      expect(Math.abs(after.column - 160)).toBeLessThan(10);
    } finally {
      await opened.close();
    }
  });

  it('prints the URL to pass and what the camera sees', async () => {
    const io = captureIO();
    const done = runHal(
      ['emulate', '--emulator', builtEmulatorPath(), '--udp-port', '0', '--no-pty'].concat([
        '--no-announce',
        '--camera',
        '0',
      ]),
      io,
    );
    running.push({ io, done });
    const deadline = Date.now() + 15_000;
    while (!io.stdout().includes('Ctrl-C') && Date.now() < deadline) {
      await new Promise((resolve) => setTimeout(resolve, 25));
    }
    expect(io.stdout()).toMatch(
      /camera at http:\/\/127\.0\.0\.1:\d+\/stream \(status http:\/\/127\.0\.0\.1:\d+\/status\), seeing an empty arena/,
    );
    expect(io.stdout()).toMatch(
      /drive it with its camera: --camera-url http:\/\/127\.0\.0\.1:\d+\n/,
    );
  });

  it.each([
    [['--world', 'w.json'], '"--world" needs --camera'],
    [['--camera-token', 'abc'], '"--camera-token" needs --camera'],
    [['--camera', '70000'], '"--camera" must be an integer in 0..65535'],
    [['--camera', '0', '--camera-token', 'a b'], '"--camera-token" must be 1..128 of'],
    [
      ['--camera', '0', '--bind', '0.0.0.0', '--key', 'abcd'],
      'refusing to serve the camera on 0.0.0.0 without a token',
    ],
  ])('refuses %j with a usage error', async (args, why) => {
    const io = captureIO();
    expect(await runHal(['emulate', '--no-announce', ...args], io)).toBe(2);
    expect(io.stderr()).toContain(why);
  });

  it('names --camera when its port is taken, and stops the robot it started', async () => {
    const taken = createServer();
    await new Promise<void>((resolve) => taken.listen(0, '127.0.0.1', resolve));
    const port = (taken.address() as AddressInfo).port;
    try {
      const io = captureIO();
      const args = ['emulate', '--emulator', builtEmulatorPath(), '--udp-port', '0', '--no-pty'];
      const code = await runHal([...args, '--no-announce', '--camera', String(port)], io);
      expect(code).toBe(1);
      expect(io.stderr()).toContain(
        `port ${port} is in use (EADDRINUSE); choose another with --camera PORT`,
      );
    } finally {
      await new Promise((resolve) => taken.close(resolve));
    }
  });

  it('fails naming the file and the field of a bad world file, before starting anything', async () => {
    const bad = join(dir, 'bad.json');
    await writeFile(bad, JSON.stringify({ ...WORLD, start: { x: 'one', y: 0 } }));
    const io = captureIO();
    const code = await runHal(
      ['emulate', '--emulator', '/nonexistent/cube-emulator', '--camera', '0', '--world', bad],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toContain(`TASK_INVALID: ${bad}: "start.x"`);
  });
});
