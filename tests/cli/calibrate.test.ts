// `hal calibrate` against the emulated robot (the firmware core as a process): the robot drives
// the straight line and the turn, and takes the computed geometry with set_config; bad answers
// and unusable robots are refused before anything changes.
import { readFile } from 'node:fs/promises';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { describe, expect, it } from 'vitest';
import { fakeTty } from '@hal/cli/testing';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator } from '../physical/emulator.js';
import { captureIO } from './capture-io.js';
import {
  calibrationDirPerTest,
  DEVICE,
  emulated,
  halOn,
  movesSince,
  stepsFor,
  TIME_SCALE,
  udpOf,
} from './calibration-rig.js';

const tmp = calibrationDirPerTest();

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
    const io = captureIO(tmp.env());
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
    expect(doc.file).toBe(join(tmp.dir(), `${DEVICE}.json`));
    const saved = JSON.parse(await readFile(doc.file, 'utf8')) as Record<string, unknown>;
    expect(saved).toMatchObject({
      version: 1,
      deviceId: DEVICE,
      wheelDiameterCm: doc.after.wheelDiameterCm,
      wheelBaseCm: doc.after.wheelBaseCm,
    });

    // the robot holds them: a session that sends nothing hears them in the robot's own hello
    const plain = halOn(emulator);
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

  it('asks a person for the measurements in a terminal, again after an answer that is no number', async () => {
    const emulator = await emulated();
    const tty = fakeTty();
    const io = { ...captureIO(tmp.env()), stdin: tty };
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
    const saved = JSON.parse(await readFile(join(tmp.dir(), `${DEVICE}.json`), 'utf8')) as Record<
      string,
      number
    >;
    expect(saved['wheelDiameterCm']).toBeCloseTo((99.5 * 4096) / (Math.PI * 21729), 4);
  });

  it('refuses an absurd measurement and changes nothing on the robot or on disk', async () => {
    const emulator = await emulated();
    const io = captureIO(tmp.env());
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
    const plain = halOn(emulator);
    await plain.initialize();
    expect(plain.identity?.config.wheel_diameter_cm).toBe(6);
    await plain.cleanup();
    await expect(readFile(join(tmp.dir(), `${DEVICE}.json`), 'utf8')).rejects.toMatchObject({
      code: 'ENOENT',
    });
  });

  it('refuses, before any motion, to calibrate a robot whose id cannot name a file', async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS,
      deviceId: 'cube one',
      pty: false,
    });
    const io = captureIO(tmp.env());
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
    expect(
      await runHal(['drive', 'forward', '0.02', ...udpOf(emulator)], captureIO(tmp.env())),
    ).toBe(0);
  });

  it('is a usage error without a terminal and without the measurements', async () => {
    const io = captureIO(tmp.env());
    expect(
      await runHal(['calibrate', '--udp', '127.0.0.1:9', '--measured-turn-deg', '360'], io),
    ).toBe(2);
    expect(io.stderr()).toMatch(
      /give --measured-distance-cm and --measured-turn-deg, or run hal calibrate in a terminal/,
    );
  });
});
