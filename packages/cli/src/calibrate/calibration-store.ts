// The robot's calibration file as `hal calibrate` and `hal calibrate camera` read and change it:
// each calibration replaces its own part and keeps the other's (the wheels keep the camera and the
// camera the wheels). A corrupt file is reported and replaced, so a calibration can still run.
import {
  calibrationOf,
  calibrationPath,
  canNameFile,
  readCalibrationFile,
  writeCalibrationFile,
} from '@hal/physical';
import type { CalibrationFile, CalibrationSource } from '@hal/physical';
import { progress } from '../io.js';
import type { CliIO } from '../io.js';

/** A calibration file as it is before a calibration changes it: the old one, else a new one. */
export type CalibrationBase = Partial<CalibrationFile> &
  Pick<CalibrationFile, 'version' | 'deviceId'>;

async function readTolerantly(
  path: string,
  io: CliIO,
  json: boolean,
  what: string,
): Promise<CalibrationFile | undefined> {
  try {
    return await readCalibrationFile(path);
  } catch (error) {
    progress(io, { json }, `warning: ${(error as Error).message}; ${what}`);
    return undefined;
  }
}

/**
 * The robot's own calibration file, if readable. A corrupt one is reported and left out, so the
 * calibration that replaces it can still run.
 */
export function tolerantSource(dir: string, io: CliIO, json: boolean): CalibrationSource {
  return async (deviceId) => {
    if (!canNameFile(deviceId)) return undefined;
    const found = await readTolerantly(
      calibrationPath(dir, deviceId),
      io,
      json,
      "calibrating from the robot's own values",
    );
    return found === undefined ? undefined : calibrationOf(found);
  };
}

/**
 * Writes the file at `path` as `change` makes it from the file there (or a new one for
 * `deviceId`): what `change` leaves alone is kept. A corrupt file is replaced.
 */
export async function updateCalibrationFile(
  path: string,
  deviceId: string,
  io: CliIO,
  json: boolean,
  change: (old: CalibrationBase) => CalibrationFile,
): Promise<void> {
  // the warning about a corrupt file was given as the robot connected
  const old = await readCalibrationFile(path).catch(() => undefined);
  const base: CalibrationBase = old?.deviceId === deviceId ? old : { version: 1, deviceId };
  if (old !== undefined && old.deviceId !== deviceId) {
    progress(io, { json }, `warning: ${path} was for robot ${old.deviceId}; replacing it`);
  }
  await writeCalibrationFile(path, change(base));
}
