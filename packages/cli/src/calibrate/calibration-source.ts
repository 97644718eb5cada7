// Which calibration a robot-facing command uses: the file `--calibration` names, else the
// robot's own file in the calibration directory (looked up by the device id its hello reports).
import type { CalibrationSource, WheelCalibration } from '@hal/physical';
import type { RobotConfig } from '@hal/types';
import { HalError } from '@hal/types';
import {
  calibrationDir,
  calibrationOf,
  calibrationPath,
  canNameFile,
  readCalibrationFile,
} from './calibration-file.js';

type Env = Readonly<Record<string, string | undefined>>;

/** The calibration in the file at `path`; INVALID_PARAMETER when there is none or it is corrupt. */
async function namedFile(path: string): Promise<{ deviceId: string; values: WheelCalibration }> {
  const file = await readCalibrationFile(path);
  if (file === undefined) {
    throw new HalError('INVALID_PARAMETER', `calibration file ${path} does not exist`, {
      details: { parameter: 'calibration', path },
    });
  }
  return { deviceId: file.deviceId, values: calibrationOf(file) };
}

/**
 * The file `--calibration` names: a path (it has a `/` or ends in `.json`), else a device id,
 * whose file in {@link calibrationDir} it is.
 */
export function calibrationFileOf(value: string, env: Env): string {
  if (value.includes('/') || value.endsWith('.json')) return value;
  return calibrationPath(calibrationDir(env), value);
}

/**
 * The source PhysicalHAL asks after each hello: the `named` file when given (refused for another robot),
 * else the robot's own file in {@link calibrationDir}, or none when it has no file.
 */
export function calibrationSource(named: string | undefined, env: Env): CalibrationSource {
  if (named !== undefined) {
    const file = calibrationFileOf(named, env);
    return async (deviceId) => {
      const found = await namedFile(file);
      if (found.deviceId !== deviceId) {
        throw new HalError(
          'INVALID_PARAMETER',
          `calibration file ${file} is for robot ${found.deviceId}, not for ${deviceId}`,
          { details: { parameter: 'calibration', path: file } },
        );
      }
      return found.values;
    };
  }
  return async (deviceId) => {
    // a robot whose id cannot name a file has no calibration file (hal calibrate says why)
    if (!canNameFile(deviceId)) return undefined;
    const found = await readCalibrationFile(calibrationPath(calibrationDir(env), deviceId));
    return found === undefined ? undefined : calibrationOf(found);
  };
}

/** The simulator's robot geometry from the file `--sim --calibration` names. */
export async function simulatedGeometry(named: string, env: Env): Promise<Partial<RobotConfig>> {
  return (await namedFile(calibrationFileOf(named, env))).values;
}
