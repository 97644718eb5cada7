// The host-side calibration file of one robot: `<dir>/<device-id>.json`, in
// $HAL_CALIBRATION_DIR, else $XDG_CONFIG_HOME/hal/calibration, else ~/.config/hal/calibration.
// Validated on every read: a corrupt file is an error naming the file, never silently ignored.
import { mkdir, readFile, rename, writeFile } from 'node:fs/promises';
import { homedir } from 'node:os';
import { dirname, join } from 'node:path';
import { DEVICE_SETTING_RANGES } from '@hal/physical';
import type { WheelCalibration } from '@hal/physical';
import { HalError } from '@hal/types';
import { z } from 'zod';

const range = (field: keyof typeof DEVICE_SETTING_RANGES) => {
  const { min, max, integer } = DEVICE_SETTING_RANGES[field];
  const n = z.number().min(min).max(max);
  return integer ? n.int() : n;
};

/** A device id safe as a file name (ids are short names such as `cube-a1b2c3`). */
const DEVICE_ID = /^[A-Za-z0-9][A-Za-z0-9._-]{0,63}$/;

export const CalibrationFileSchema = z.object({
  version: z.literal(1).describe('File format version'),
  deviceId: z.string().regex(DEVICE_ID).describe("The robot's device id (its hello's device_id)"),
  wheelDiameterCm: range('wheel_diameter_cm').describe('Calibrated wheel diameter, cm'),
  wheelBaseCm: range('wheel_base_cm').describe('Calibrated wheel base, cm'),
  stepsPerRevolution: range('steps_per_revolution').optional().describe('Steps per revolution'),
  calibratedAt: z.iso.datetime().describe('When the measurement was made (ISO 8601, UTC)'),
  measurements: z
    .object({
      straightSteps: z.number().int().describe('Steps per wheel of the straight run'),
      measuredDistanceCm: z.number().positive().describe('Distance the user measured, cm'),
      turnSteps: z.number().int().describe('Steps per wheel of the turn in place'),
      measuredTurnDeg: z.number().positive().describe('Angle the user measured, degrees'),
    })
    .optional()
    .describe('What the values were computed from'),
});
export type CalibrationFile = z.infer<typeof CalibrationFileSchema>;

/** The directory calibration files live in, from `env`. */
export function calibrationDir(env: Readonly<Record<string, string | undefined>>): string {
  const explicit = env['HAL_CALIBRATION_DIR'];
  if (explicit !== undefined && explicit !== '') return explicit;
  const xdg = env['XDG_CONFIG_HOME'];
  const config = xdg !== undefined && xdg !== '' ? xdg : join(env['HOME'] ?? homedir(), '.config');
  return join(config, 'hal', 'calibration');
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
  await mkdir(dirname(path), { recursive: true });
  const temporary = `${path}.${process.pid}.tmp`;
  await writeFile(temporary, `${JSON.stringify(checked, null, 2)}\n`, 'utf8');
  await rename(temporary, path);
}

/** The wheel geometry a file holds, as PhysicalHAL and the simulator take it. */
export function calibrationOf(file: CalibrationFile): WheelCalibration {
  return {
    wheelDiameterCm: file.wheelDiameterCm,
    wheelBaseCm: file.wheelBaseCm,
    ...(file.stepsPerRevolution === undefined
      ? {}
      : { stepsPerRevolution: file.stepsPerRevolution }),
  };
}
