// Which calibration a PhysicalHAL sends after hello: a named file (`hal --calibration`), else
// the robot's own file in the calibration directory (looked up by the device id its hello reports).
import { HalError } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { CalibrationSource, RobotCalibration } from '../hal/calibration.js';
import {
  calibrationDir,
  calibrationOf,
  calibrationPath,
  canNameFile,
  readCalibrationFile,
} from './calibration-file.js';

type Env = Readonly<Record<string, string | undefined>>;

/** The calibration in the file at `path`; INVALID_PARAMETER when there is none or it is corrupt. */
async function namedFile(path: string): Promise<{ deviceId: string; values: RobotCalibration }> {
  const file = await readCalibrationFile(path);
  if (file === undefined) {
    throw new HalError('INVALID_PARAMETER', `calibration file ${path} does not exist`, {
      details: { parameter: 'calibration', path },
    });
  }
  return { deviceId: file.deviceId, values: calibrationOf(file) };
}

/**
 * The file `named` names (`--calibration`): a path (it has a `/` or ends in `.json`), else a device id,
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
    // no $HAL_CALIBRATION_DIR, $XDG_CONFIG_HOME or $HOME (a bare service): no directory, no file
    if (
      !['HAL_CALIBRATION_DIR', 'XDG_CONFIG_HOME', 'HOME', 'USERPROFILE'].some((name) => env[name])
    ) {
      return undefined;
    }
    const found = await readCalibrationFile(calibrationPath(calibrationDir(env), deviceId));
    return found === undefined ? undefined : calibrationOf(found);
  };
}

/** The wheel geometry in the file `named` names, for a simulated robot (`--sim --calibration`). */
export async function calibratedGeometry(named: string, env: Env): Promise<Partial<RobotConfig>> {
  return (await namedFile(calibrationFileOf(named, env))).values.wheels ?? {};
}
