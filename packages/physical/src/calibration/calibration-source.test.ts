import { mkdtemp, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { writeCalibrationFile } from './calibration-file.js';
import type { CalibrationFile } from './calibration-file.js';
import { calibrationFileOf, calibrationSource } from './calibration-source.js';

const FILE: CalibrationFile = {
  version: 1,
  deviceId: 'cube-7',
  wheelDiameterCm: 6.6,
  wheelBaseCm: 10.4,
  calibratedAt: '2026-12-01T20:00:00.000Z',
};

let dir: string;
beforeEach(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-calibration-source-'));
});
afterEach(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('calibrationFileOf', () => {
  it('takes a value with a slash or a .json end as a path, anything else as a device id', () => {
    const env = { HAL_CALIBRATION_DIR: '/c' };
    expect(calibrationFileOf('./mine.json', env)).toBe('./mine.json');
    expect(calibrationFileOf('mine.json', env)).toBe('mine.json');
    expect(calibrationFileOf('cube-7', env)).toBe('/c/cube-7.json');
  });
});

describe('calibrationSource', () => {
  it("finds the robot's own file in the calibration directory, and nothing for another robot", async () => {
    await writeCalibrationFile(join(dir, 'cube-7.json'), FILE);
    const source = calibrationSource(undefined, { HAL_CALIBRATION_DIR: dir });
    expect(await source('cube-7')).toEqual({ wheels: { wheelDiameterCm: 6.6, wheelBaseCm: 10.4 } });
    expect(await source('cube-8')).toBeUndefined();
    expect(await calibrationSource(undefined, {})('cube-7')).toBeUndefined();
    // an id that cannot name a file has none (rather than failing every command)
    expect(await source('../cube-7')).toBeUndefined();
  });

  it('refuses a named file that belongs to another robot, or that does not exist', async () => {
    const path = join(dir, 'cube-7.json');
    await writeCalibrationFile(path, FILE);
    await expect(calibrationSource(path, {})('cube-8')).rejects.toThrow(
      `calibration file ${path} is for robot cube-7, not for cube-8`,
    );
    await expect(calibrationSource(join(dir, 'none.json'), {})('cube-7')).rejects.toThrow(
      /does not exist/,
    );
  });
});
