// `hal calibrate` against the emulated robot (the firmware core as a process): the robot drives
// the straight line and the turn, takes the computed geometry with set_config, and every later
// session (a new process of the emulator, which forgets its RAM) gets it again after hello.
import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { calibrationSource, runHal, writeCalibrationFile } from '@hal/cli';
import { PhysicalHAL } from '@hal/physical';
import { afterAll, afterEach, beforeEach, describe, expect, it } from 'vitest';
import { fakeTty } from '../../packages/cli/src/teleop/fake-tty.fixture.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator, EmulatorEvent } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';

const TIME_SCALE = 10;
const DEVICE = 'cube-calib';
/** The steps the firmware makes for `cm` on wheels of `diameterCm` (4096 a turn; it truncates). */
const stepsFor = (cm: number, diameterCm: number) =>
  Math.trunc((cm * 4096) / (Math.PI * diameterCm));

let dir: string;
let env: Record<string, string>;
beforeEach(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-calibrate-'));
  env = { HAL_CALIBRATION_DIR: dir };
});
afterEach(async () => {
  await stopAllEmulators();
  await rm(dir, { recursive: true, force: true });
});
afterAll(stopAllEmulators);

const emulated = () => startEmulator({ timeScale: TIME_SCALE, deviceId: DEVICE, pty: false });
const udpOf = (e: Emulator) => [
  '--udp',
  `127.0.0.1:${e.udpPort}`,
  '--time-scale',
  String(TIME_SCALE),
];
const movesSince = (e: Emulator, from: number): EmulatorEvent[] =>
  e.events.slice(from).filter((event) => event.event === 'move_started');

interface CalibrateDoc {
  deviceId: string;
  before: { wheelDiameterCm: number; wheelBaseCm: number };
  after: { wheelDiameterCm: number; wheelBaseCm: number };
  straight: { leftSteps: number; rightSteps: number };
  file: string;
}

describe('hal calibrate on the emulated robot', () => {
  it('computes the geometry from the measured line and turn, sends it and saves it', async () => {
    const emulator = await emulated();
    const io = captureIO(env);
    const code = await runHal(
      [
        '--json',
        'calibrate',
        ...udpOf(emulator),
        '--measured-distance-cm',
        '102',
        '--measured-turn-deg',
        '350',
      ],
      io,
    );
    expect(code, io.stderr()).toBe(0);
    const doc = io.jsonLines()[0] as CalibrateDoc;
    // the robot drove 100 cm on nominal 6 cm wheels: 21729 steps; measured 102 cm, so 6.12 cm
    const moves = movesSince(emulator, 0);
    expect(moves.map((m) => [m['left_steps'], m['right_steps']])).toEqual([
      [21729, 21729],
      [-6826, 6827],
    ]);
    const diameter = (102 * 4096) / (Math.PI * 21729);
    const base = (360 * 6826.5 * diameter) / (4096 * 350);
    expect(doc.before).toMatchObject({ wheelDiameterCm: 6, wheelBaseCm: 10 });
    expect(doc.after.wheelDiameterCm).toBeCloseTo(diameter, 3);
    expect(doc.after.wheelBaseCm).toBeCloseTo(base, 3);
    // the robot was told with set_config, after both motions
    const configs = emulator.events.filter((e) => e.event === 'config');
    expect(configs).toHaveLength(1);
    expect(configs[0]).toMatchObject({
      wheel_diameter_cm: doc.after.wheelDiameterCm,
      wheel_base_cm: doc.after.wheelBaseCm,
      steps_per_revolution: 4096,
    });
    expect(emulator.events.indexOf(configs[0]!)).toBeGreaterThan(
      emulator.events.indexOf(moves[1]!),
    );
    expect(doc.file).toBe(join(dir, `${DEVICE}.json`));
    const saved = JSON.parse(await readFile(doc.file, 'utf8')) as Record<string, unknown>;
    expect(saved).toMatchObject({
      version: 1,
      deviceId: DEVICE,
      wheelDiameterCm: doc.after.wheelDiameterCm,
      wheelBaseCm: doc.after.wheelBaseCm,
    });

    // the robot holds them: a session that sends nothing hears them in the robot's own hello
    const plain = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: DEVICE,
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    await plain.initialize();
    expect(plain.identity?.config).toMatchObject({
      wheel_diameter_cm: doc.after.wheelDiameterCm,
      wheel_base_cm: doc.after.wheelBaseCm,
    });
    // and drives with them: 50 cm is fewer steps on the larger wheel
    const before = emulator.events.length;
    expect((await plain.locomotion.moveForward(50)).success).toBe(true);
    expect(movesSince(emulator, before)[0]).toMatchObject({
      left_steps: stepsFor(50, doc.after.wheelDiameterCm),
    });
    await plain.cleanup();
  });

  it('sends the saved calibration after hello to a robot that restarted and forgot it', async () => {
    const first = await emulated();
    const calibrated = await runHal(
      ['calibrate', ...udpOf(first), '--measured-distance-cm', '97', '--measured-turn-deg', '372'],
      captureIO(env),
    );
    expect(calibrated).toBe(0);
    await first.stop();

    // a new robot process: its RAM holds the firmware defaults again
    const robot = await emulated();
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: DEVICE,
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: robot.udpPort },
      },
      { timeScale: TIME_SCALE, calibration: calibrationSource(undefined, env) },
    );
    await hal.initialize();
    // its hello said 6 cm; the HAL answered with set_config before anything else
    expect(hal.identity?.config.wheel_diameter_cm).toBe(6);
    const saved = JSON.parse(await readFile(join(dir, `${DEVICE}.json`), 'utf8')) as {
      wheelDiameterCm: number;
      wheelBaseCm: number;
    };
    expect(saved.wheelDiameterCm).toBeCloseTo((97 * 4096) / (Math.PI * 21729), 3);
    expect(hal.robotConfig).toMatchObject({
      wheelDiameterCm: saved.wheelDiameterCm,
      wheelBaseCm: saved.wheelBaseCm,
    });
    await robot.waitFor((e) => e.event === 'config', 5000);
    expect(robot.events.filter((e) => e.event === 'config')).toEqual([
      expect.objectContaining({
        wheel_diameter_cm: saved.wheelDiameterCm,
        wheel_base_cm: saved.wheelBaseCm,
      }),
    ]);
    const before = robot.events.length;
    expect((await hal.locomotion.moveForward(50)).success).toBe(true);
    expect(movesSince(robot, before)[0]).toMatchObject({
      left_steps: stepsFor(50, saved.wheelDiameterCm),
    });
    await hal.cleanup();

    // hal drive does the same through its own PhysicalHAL, in a session of its own
    const drive = captureIO(env);
    const next = robot.events.length;
    expect(await runHal(['--json', 'drive', 'forward', '0.2', ...udpOf(robot)], drive)).toBe(0);
    expect(movesSince(robot, next)[0]).toMatchObject({
      left_steps: stepsFor(20, saved.wheelDiameterCm),
    });
    const moved = drive.jsonLines()[0] as { pose: { position: { x: number } } };
    expect(moved.pose.position.x).toBeCloseTo(0.2, 3);
  });

  it('gives a robot that restarts mid-session its calibration again, in the new session', async () => {
    await writeCalibrationFile(join(dir, `${DEVICE}.json`), {
      version: 1,
      deviceId: DEVICE,
      wheelDiameterCm: 6.3,
      wheelBaseCm: 10.2,
      calibratedAt: new Date().toISOString(),
    });
    const first = await emulated();
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: DEVICE,
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: first.udpPort },
      },
      {
        timeScale: TIME_SCALE,
        reconnectIntervalMs: 100,
        calibration: calibrationSource(undefined, env),
      },
    );
    try {
      await hal.initialize();
      await first.waitFor((e) => e.event === 'config', 5000);
      // a power cut: the new robot boots with the firmware's defaults on the same port
      await first.kill();
      const second = await startEmulator({
        timeScale: TIME_SCALE,
        deviceId: DEVICE,
        udpPort: first.udpPort,
        pty: false,
      });
      const config = await second.waitFor((e) => e.event === 'config', 15_000);
      expect(config).toMatchObject({ wheel_diameter_cm: 6.3, wheel_base_cm: 10.2 });
      await expect.poll(() => hal.linkState, { timeout: 5000 }).toBe('connected');
      const before = second.events.length;
      expect((await hal.locomotion.moveForward(10)).success).toBe(true);
      expect(movesSince(second, before)[0]).toMatchObject({ left_steps: stepsFor(10, 6.3) });
    } finally {
      await hal.cleanup();
    }
  });

  it('asks a person for the measurements in a terminal, again after an answer that is no number', async () => {
    const emulator = await emulated();
    const tty = fakeTty();
    const io = { ...captureIO(env), stdin: tty };
    const run = runHal(['calibrate', ...udpOf(emulator)], io);
    const answer = async (prompt: RegExp, text: string) => {
      await expect.poll(() => io.stderr(), { timeout: 20_000 }).toMatch(prompt);
      tty.write(`${text}\n`);
    };
    await answer(/press Enter when it has room/, '');
    await answer(/distance it actually travelled, cm: $/, 'about a metre');
    await answer(/a number > 0 cm, please/, '99.5');
    await answer(/press Enter to turn/, '');
    await answer(/angle it actually turned, degrees .*: $/, '361');
    expect(await run, io.stderr()).toBe(0);
    expect(io.stdout()).toMatch(/wheel diameter 6\.000 cm -> 5\.970 cm/);
    const saved = JSON.parse(await readFile(join(dir, `${DEVICE}.json`), 'utf8')) as Record<
      string,
      number
    >;
    expect(saved['wheelDiameterCm']).toBeCloseTo((99.5 * 4096) / (Math.PI * 21729), 4);
  });

  it('refuses an absurd measurement and changes nothing on the robot or on disk', async () => {
    const emulator = await emulated();
    const io = captureIO(env);
    const code = await runHal(
      [
        'calibrate',
        ...udpOf(emulator),
        '--measured-distance-cm',
        '1',
        '--measured-turn-deg',
        '360',
      ],
      io,
    );
    expect(code).toBe(1);
    expect(io.stderr()).toMatch(
      /hal: INVALID_PARAMETER: "measuredDistanceCm" 1 cm is more than 2x from the 100\.0 cm/,
    );
    const plain = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: DEVICE,
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    await plain.initialize();
    expect(plain.identity?.config.wheel_diameter_cm).toBe(6);
    await plain.cleanup();
    await expect(readFile(join(dir, `${DEVICE}.json`), 'utf8')).rejects.toMatchObject({
      code: 'ENOENT',
    });
  });

  it("fails a robot command naming the robot's corrupt calibration file, and drives nothing", async () => {
    const emulator = await emulated();
    const path = join(dir, `${DEVICE}.json`);
    await writeFile(path, JSON.stringify({ version: 1, deviceId: DEVICE, wheelDiameterCm: 'six' }));
    const io = captureIO(env);
    expect(await runHal(['drive', 'forward', '0.05', ...udpOf(emulator)], io)).toBe(1);
    expect(io.stderr()).toMatch(
      `hal: INVALID_PARAMETER: calibration file ${path}: "wheelDiameterCm" Invalid input: expected number`,
    );
    expect(movesSince(emulator, 0)).toEqual([]);
    // hal calibrate replaces it, starting from the robot's own values
    const calibrate = captureIO(env);
    const argv = [
      'calibrate',
      ...udpOf(emulator),
      '--measured-distance-cm',
      '100',
      '--measured-turn-deg',
      '360',
    ];
    expect(await runHal(argv, calibrate), calibrate.stderr()).toBe(0);
    expect(calibrate.stderr()).toMatch(
      /warning: calibration file .* calibrating from the robot's own values/,
    );
    expect(JSON.parse(await readFile(path, 'utf8'))).toMatchObject({
      deviceId: DEVICE,
      version: 1,
    });
  });

  it('refuses, before any motion, to calibrate a robot whose id cannot name a file', async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      deviceId: 'cube one',
      pty: false,
    });
    const io = captureIO(env);
    const argv = [
      'calibrate',
      ...udpOf(emulator),
      '--measured-distance-cm',
      '100',
      '--measured-turn-deg',
      '360',
    ];
    expect(await runHal(argv, io)).toBe(1);
    expect(io.stderr()).toMatch(
      /hal: INVALID_PARAMETER: device id "cube one" cannot name a calibration file/,
    );
    expect(movesSince(emulator, 0)).toEqual([]);
    // other commands drive it with its own geometry
    expect(await runHal(['drive', 'forward', '0.02', ...udpOf(emulator)], captureIO(env))).toBe(0);
  });

  it('is a usage error without a terminal and without the measurements', async () => {
    const io = captureIO(env);
    expect(
      await runHal(['calibrate', '--udp', '127.0.0.1:9', '--measured-turn-deg', '360'], io),
    ).toBe(2);
    expect(io.stderr()).toMatch(
      /give --measured-distance-cm and --measured-turn-deg, or run hal calibrate in a terminal/,
    );
  });
});
