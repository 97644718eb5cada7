import { mkdtemp, readdir, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import {
  calibrationDir,
  calibrationOf,
  calibrationPath,
  readCalibrationFile,
  writeCalibrationFile,
} from './calibration-file.js';
import type { CalibrationFile } from './calibration-file.js';
import { V1_CAMERA } from '@hal/types';

const FILE: CalibrationFile = {
  version: 1,
  deviceId: 'cube-a1b2c3',
  wheelDiameterCm: 6.12,
  wheelBaseCm: 10.31,
  calibratedAt: '2026-12-01T20:00:00.000Z',
  measurements: {
    straightSteps: 21730,
    measuredDistanceCm: 102,
    turnSteps: 6827,
    measuredTurnDeg: 355,
  },
};

let dir: string;
beforeEach(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-calibration-'));
});
afterEach(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('calibrationDir', () => {
  it('takes $HAL_CALIBRATION_DIR, then $XDG_CONFIG_HOME/hal/calibration, then ~/.config', () => {
    expect(calibrationDir({ HAL_CALIBRATION_DIR: '/a', XDG_CONFIG_HOME: '/b' })).toBe('/a');
    expect(calibrationDir({ XDG_CONFIG_HOME: '/b', HOME: '/h' })).toBe('/b/hal/calibration');
    expect(calibrationDir({ HOME: '/h' })).toBe('/h/.config/hal/calibration');
    expect(calibrationDir({ XDG_CONFIG_HOME: '/b/' })).toBe('/b/hal/calibration');
    expect(() => calibrationDir({})).toThrow(/no calibration directory: set \$HAL_CALIBRATION_DIR/);
  });
});

describe('calibrationPath', () => {
  it('names the file by device id and refuses an id that would leave the directory', () => {
    expect(calibrationPath('/c', 'cube-1')).toBe('/c/cube-1.json');
    expect(() => calibrationPath('/c', '../etc/passwd')).toThrow(/cannot name a calibration file/);
    expect(() => calibrationPath('/c', '')).toThrow(/cannot name a calibration file/);
  });
});

describe('the calibration file', () => {
  it('reads back what was written, in a directory it creates', async () => {
    const path = calibrationPath(join(dir, 'nested', 'calibration'), FILE.deviceId);
    await writeCalibrationFile(path, FILE);
    expect(await readCalibrationFile(path)).toEqual(FILE);
    expect(calibrationOf(FILE)).toEqual({ wheels: { wheelDiameterCm: 6.12, wheelBaseCm: 10.31 } });
    expect(await readdir(join(dir, 'nested', 'calibration'))).toEqual(['cube-a1b2c3.json']);
  });

  it('holds a camera model beside the wheels, or alone', async () => {
    const camera = {
      model: { ...V1_CAMERA, tiltDeg: 17.5 },
      calibratedAt: '2026-12-02T20:00:00.000Z',
      residualM: 0.004,
      measurements: [{ colour: 'red', distanceM: 0.5, baseRow: 170 }],
    };
    const both = join(dir, 'both.json');
    await writeCalibrationFile(both, { ...FILE, camera });
    expect(calibrationOf((await readCalibrationFile(both))!)).toEqual({
      wheels: { wheelDiameterCm: 6.12, wheelBaseCm: 10.31 },
      camera: { ...V1_CAMERA, tiltDeg: 17.5 },
    });
    const alone = join(dir, 'alone.json');
    const { wheelDiameterCm: _d, wheelBaseCm: _b, measurements: _m, ...rest } = FILE;
    await writeCalibrationFile(alone, { ...rest, camera });
    expect(calibrationOf((await readCalibrationFile(alone))!)).toEqual({
      camera: { ...V1_CAMERA, tiltDeg: 17.5 },
    });
  });

  it('is refused when it holds half the wheels or nothing at all', async () => {
    const path = join(dir, 'cube-1.json');
    const { wheelBaseCm: _b, ...half } = FILE;
    await writeFile(path, JSON.stringify(half));
    await expect(readCalibrationFile(path)).rejects.toThrow(/"wheelDiameterCm" must be given with/);
    const { wheelDiameterCm: _d, ...none } = half;
    await writeFile(path, JSON.stringify(none));
    await expect(readCalibrationFile(path)).rejects.toThrow(/"wheelDiameterCm" is missing/);
  });

  it('is absent (undefined) when there is no file for the device', async () => {
    expect(await readCalibrationFile(join(dir, 'nobody.json'))).toBeUndefined();
  });

  it('is refused with the file and the reason when it is not JSON', async () => {
    const path = join(dir, 'cube-1.json');
    await writeFile(path, '{"version": 1, "wheelDiam');
    await expect(readCalibrationFile(path)).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
      message: expect.stringContaining(`calibration file ${path} is not valid JSON`),
    });
  });

  it('is refused naming the field when a value is out of the firmware range', async () => {
    const path = join(dir, 'cube-1.json');
    await writeFile(path, JSON.stringify({ ...FILE, wheelBaseCm: 0 }));
    await expect(readCalibrationFile(path)).rejects.toMatchObject({
      code: 'INVALID_PARAMETER',
      message: expect.stringMatching(/"wheelBaseCm" .*>=1/),
    });
    await writeFile(path, JSON.stringify({ ...FILE, version: 2 }));
    await expect(readCalibrationFile(path)).rejects.toThrow(/"version"/);
  });

  it('refuses to write values the robot would refuse, leaving the old file', async () => {
    const path = join(dir, 'cube-1.json');
    await writeCalibrationFile(path, FILE);
    await expect(
      writeCalibrationFile(path, { ...FILE, wheelDiameterCm: Number.NaN }),
    ).rejects.toThrow();
    expect(await readCalibrationFile(path)).toEqual(FILE);
  });
});
