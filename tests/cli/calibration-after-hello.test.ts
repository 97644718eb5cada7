// Every session sends the robot's saved calibration with set_config after hello: a new process
// of the emulator (which forgets its RAM), a robot that restarts mid-session, and `hal drive`.
import { readFile, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { runHal } from '@hal/cli';
import { calibrationSource, writeCalibrationFile } from '@hal/physical';
import { describe, expect, it } from 'vitest';
import { captureIO } from './capture-io.js';
import {
  calibrationDirPerTest,
  DEVICE,
  emulated,
  halOn,
  movesSince,
  stepsFor,
  udpOf,
} from './calibration-rig.js';

const tmp = calibrationDirPerTest();

describe('the saved calibration, after every hello', () => {
  it('sends the saved calibration after hello to a robot that restarted and forgot it', async () => {
    const first = await emulated();
    const calibrated = await runHal(
      ['calibrate', ...udpOf(first), '--measured-distance-cm', '97', '--measured-turn-deg', '372'],
      captureIO(tmp.env()),
    );
    expect(calibrated).toBe(0);
    await first.stop();

    // a new robot process: its RAM holds the firmware defaults again
    const robot = await emulated();
    const hal = halOn(robot, { calibration: calibrationSource(undefined, tmp.env()) });
    await hal.initialize();
    // its hello said 6 cm; the HAL answered with set_config before anything else
    expect(hal.identity?.config.wheel_diameter_cm).toBe(6);
    const saved = JSON.parse(await readFile(join(tmp.dir(), `${DEVICE}.json`), 'utf8')) as {
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
    const drive = captureIO(tmp.env());
    const next = robot.events.length;
    expect(await runHal(['--json', 'drive', 'forward', '0.2', ...udpOf(robot)], drive)).toBe(0);
    expect(movesSince(robot, next)[0]).toMatchObject({
      left_steps: stepsFor(20, saved.wheelDiameterCm),
    });
    const moved = drive.jsonLines()[0] as { pose: { position: { x: number } } };
    expect(moved.pose.position.x).toBeCloseTo(0.2, 3);
  });

  it('gives a robot that restarts mid-session its calibration again, in the new session', async () => {
    await writeCalibrationFile(join(tmp.dir(), `${DEVICE}.json`), {
      version: 1,
      deviceId: DEVICE,
      wheelDiameterCm: 6.3,
      wheelBaseCm: 10.2,
      calibratedAt: new Date().toISOString(),
    });
    const first = await emulated();
    const hal = halOn(first, {
      reconnectIntervalMs: 100,
      calibration: calibrationSource(undefined, tmp.env()),
    });
    try {
      await hal.initialize();
      await first.waitFor((e) => e.event === 'config', 5000);
      // a power cut: the new robot boots with the firmware's defaults on the same port
      await first.kill();
      const second = await emulated(first.udpPort);
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

  it("fails a robot command naming the robot's corrupt calibration file, and drives nothing", async () => {
    const emulator = await emulated();
    const path = join(tmp.dir(), `${DEVICE}.json`);
    await writeFile(path, JSON.stringify({ version: 1, deviceId: DEVICE, wheelDiameterCm: 'six' }));
    const io = captureIO(tmp.env());
    expect(await runHal(['drive', 'forward', '0.05', ...udpOf(emulator)], io)).toBe(1);
    expect(io.stderr()).toMatch(
      `hal: INVALID_PARAMETER: calibration file ${path}: "wheelDiameterCm" Invalid input: expected number`,
    );
    expect(movesSince(emulator, 0)).toEqual([]);
    // hal calibrate replaces it, starting from the robot's own values
    const calibrate = captureIO(tmp.env());
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
});
