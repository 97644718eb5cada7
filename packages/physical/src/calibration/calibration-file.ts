// The host-side calibration file of one robot: `<dir>/<device-id>.json`, in
// $HAL_CALIBRATION_DIR, else $XDG_CONFIG_HOME/hal/calibration, else ~/.config/hal/calibration.
// Validated on every read: a corrupt file is an error naming the file, never silently ignored.
// Node's file system is loaded when a file is read or written, so a browser bundle of this
// package never meets it.
import { CameraModelSchema, HalError } from '@hal/types';
import { z } from 'zod';
import type { RobotCalibration } from '../hal/calibration.js';
import { DEVICE_SETTING_RANGES } from '../protocol/device-config.js';

type Env = Readonly<Record<string, string | undefined>>;

/** `dir` and `name` joined with `/` (which Node takes on every platform). */
const join = (...parts: string[]) =>
  parts.map((part, i) => (i === 0 ? part.replace(/\/+$/, '') : part)).join('/');
const dirname = (path: string) => path.slice(0, Math.max(path.lastIndexOf('/'), 0)) || '/';

const range = (field: keyof typeof DEVICE_SETTING_RANGES) => {
  const { min, max, integer } = DEVICE_SETTING_RANGES[field];
  const n = z.number().min(min).max(max);
  return integer ? n.int() : n;
};

/** A device id safe as a file name (ids are short names such as `cube-a1b2c3`). */
const DEVICE_ID = /^[A-Za-z0-9][A-Za-z0-9._-]{0,63}$/;

/** What `hal calibrate camera` fitted the camera model from. */
export const CameraMeasurementSchema = z
  .object({
    colour: z.string().describe('The colour of the target'),
    distanceM: z
      .number()
      .positive()
      .describe("Measured distance from the robot's centre to the target's near face, m"),
    baseRow: z.number().describe("The image row of the target's base (its lower edge), pixels"),
  })
  .describe('One sighting of the target');

export const CalibrationFileSchema = z
  .object({
    version: z.literal(1).describe('File format version'),
    deviceId: z.string().regex(DEVICE_ID).describe("The robot's device id (its hello's device_id)"),
    wheelDiameterCm: range('wheel_diameter_cm')
      .optional()
      .describe('Calibrated wheel diameter, cm (`hal calibrate`)'),
    wheelBaseCm: range('wheel_base_cm')
      .optional()
      .describe('Calibrated wheel base, cm (`hal calibrate`)'),
    stepsPerRevolution: range('steps_per_revolution').optional().describe('Steps per revolution'),
    calibratedAt: z.iso
      .datetime()
      .describe('When the last calibration in the file was made (ISO 8601, UTC)'),
    measurements: z
      .object({
        straightSteps: z.number().int().describe('Steps per wheel of the straight run'),
        measuredDistanceCm: z.number().positive().describe('Distance the user measured, cm'),
        turnSteps: z.number().int().describe('Steps per wheel of the turn in place'),
        measuredTurnDeg: z.number().positive().describe('Angle the user measured, degrees'),
      })
      .optional()
      .describe('What the values were computed from'),
    camera: z
      .object({
        model: CameraModelSchema.describe('The camera model, its tilt (and height) fitted'),
        calibratedAt: z.iso.datetime().describe('When the camera was calibrated (ISO 8601, UTC)'),
        residualM: z
          .number()
          .min(0)
          .describe('Largest distance error of the fitted model over the sightings, m'),
        measurements: z.array(CameraMeasurementSchema).min(1).describe('The sightings'),
      })
      .optional()
      .describe('The camera (`hal calibrate camera`)'),
  })
  .refine((file) => (file.wheelDiameterCm === undefined) === (file.wheelBaseCm === undefined), {
    message: 'must be given with "wheelBaseCm" (both wheel values or neither)',
    path: ['wheelDiameterCm'],
  })
  .refine((file) => file.wheelDiameterCm !== undefined || file.camera !== undefined, {
    message: 'is missing: a calibration holds the wheels, the camera or both',
    path: ['wheelDiameterCm'],
  });
export type CalibrationFile = z.infer<typeof CalibrationFileSchema>;

/**
 * The directory calibration files live in, from `env`: `$HAL_CALIBRATION_DIR`, else
 * `$XDG_CONFIG_HOME/hal/calibration`, else `$HOME/.config/hal/calibration` (`%USERPROFILE%` on
 * Windows). INVALID_PARAMETER when none of them is set.
 */
export function calibrationDir(env: Env): string {
  const set = (name: string) => {
    const value = env[name];
    return value === undefined || value === '' ? undefined : value;
  };
  const explicit = set('HAL_CALIBRATION_DIR');
  if (explicit !== undefined) return explicit;
  const xdg = set('XDG_CONFIG_HOME');
  if (xdg !== undefined) return join(xdg, 'hal', 'calibration');
  const home = set('HOME') ?? set('USERPROFILE');
  if (home === undefined) {
    throw new HalError(
      'INVALID_PARAMETER',
      'no calibration directory: set $HAL_CALIBRATION_DIR (or $XDG_CONFIG_HOME, or $HOME)',
      { details: { parameter: 'HAL_CALIBRATION_DIR' } },
    );
  }
  return join(home, '.config', 'hal', 'calibration');
}

/** Whether `deviceId` can name a calibration file (no path separators, no dot first). */
export function canNameFile(deviceId: string): boolean {
  return DEVICE_ID.test(deviceId);
}

/** The file of `deviceId` in `dir`; INVALID_PARAMETER for an id that is not a safe file name. */
export function calibrationPath(dir: string, deviceId: string): string {
  if (!canNameFile(deviceId)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `device id "${deviceId}" cannot name a calibration file (letters, digits, . _ - only)`,
      { details: { parameter: 'deviceId', received: deviceId } },
    );
  }
  return join(dir, `${deviceId}.json`);
}

/**
 * Reads and checks the calibration file at `path`: undefined when there is none; INVALID_PARAMETER
 * naming the file and the bad field when it is not valid JSON or not a calibration.
 */
export async function readCalibrationFile(path: string): Promise<CalibrationFile | undefined> {
  const { readFile } = await import('node:fs/promises');
  let text: string;
  try {
    text = await readFile(path, 'utf8');
  } catch (error) {
    if ((error as NodeJS.ErrnoException).code === 'ENOENT') return undefined;
    throw new HalError(
      'INVALID_PARAMETER',
      `cannot read calibration file ${path}: ${String(error)}`,
      {
        cause: error,
      },
    );
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (error) {
    throw new HalError(
      'INVALID_PARAMETER',
      `calibration file ${path} is not valid JSON (${(error as Error).message}): run "hal calibrate" again or delete it`,
      { cause: error },
    );
  }
  const parsed = CalibrationFileSchema.safeParse(json);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const field = issue?.path.join('.') || 'file';
    throw new HalError(
      'INVALID_PARAMETER',
      `calibration file ${path}: "${field}" ${issue?.message ?? 'is invalid'}: run "hal calibrate" again or delete it`,
      { details: { parameter: field, path } },
    );
  }
  return parsed.data;
}

/** Writes `file` to `path` (creating the directory), atomically: a crash leaves the old file. */
export async function writeCalibrationFile(path: string, file: CalibrationFile): Promise<void> {
  const checked = CalibrationFileSchema.parse(file);
  const { mkdir, rename, writeFile } = await import('node:fs/promises');
  await mkdir(dirname(path), { recursive: true });
  const temporary = `${path}.${process.pid}.tmp`;
  await writeFile(temporary, `${JSON.stringify(checked, null, 2)}\n`, 'utf8');
  await rename(temporary, path);
}

/** The wheel geometry and camera model a file holds, as PhysicalHAL takes them. */
export function calibrationOf(file: CalibrationFile): RobotCalibration {
  const calibration: RobotCalibration = {};
  if (file.wheelDiameterCm !== undefined && file.wheelBaseCm !== undefined) {
    calibration.wheels = {
      wheelDiameterCm: file.wheelDiameterCm,
      wheelBaseCm: file.wheelBaseCm,
      ...(file.stepsPerRevolution === undefined
        ? {}
        : { stepsPerRevolution: file.stepsPerRevolution }),
    };
  }
  if (file.camera !== undefined) calibration.camera = file.camera.model;
  return calibration;
}
