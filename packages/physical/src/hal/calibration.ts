// A robot's measured wheel geometry (`hal calibrate`), sent with `set_config` after every hello:
// the firmware keeps its geometry in RAM only, so each new session (and each reconnect after a
// robot restart) must give it again. Checked against the firmware's ranges before it is sent.
import { HalError, isHalError } from '@hal/types';
import type { CameraModel } from '@hal/types';
import { DEVICE_SETTING_RANGES } from '../protocol/device-config.js';
import type { DeviceSettings } from '../protocol/device-config.js';
import type { DeviceConfig, RequestParams, SetConfigReply } from '../protocol/schemas.js';

/** Wheel geometry measured for one robot. */
export interface WheelCalibration {
  /** Effective wheel diameter, cm (the firmware takes 0.5..50). */
  wheelDiameterCm: number;
  /** Distance between the wheel contact points, cm (the firmware takes 1..100). */
  wheelBaseCm: number;
  /** Motor steps per wheel revolution (the settings table's range), when measured; else the robot's own. */
  stepsPerRevolution?: number;
}

/** A robot's calibration: its wheel geometry (`hal calibrate`), its camera (`hal calibrate camera`), or both. */
export interface RobotCalibration {
  wheels?: WheelCalibration;
  camera?: CameraModel;
}

/**
 * Where PhysicalHAL finds a robot's calibration once its `hello` names the robot: undefined when
 * there is none (the robot's own geometry is used), a wheel geometry alone, or a
 * {@link RobotCalibration}. A failure fails `initialize()`.
 */
export type CalibrationSource = (
  deviceId: string,
) =>
  | WheelCalibration
  | RobotCalibration
  | undefined
  | Promise<WheelCalibration | RobotCalibration | undefined>;

/** What a {@link CalibrationSource} answered, as a {@link RobotCalibration}. */
export function robotCalibration(
  found: WheelCalibration | RobotCalibration | undefined,
): RobotCalibration {
  if (found === undefined) return {};
  return 'wheelDiameterCm' in found ? { wheels: found } : found;
}

type CalibrationParams = RequestParams['set_config'];

function checked(field: keyof DeviceSettings, value: number): number {
  const { min, max, integer, unit } = DEVICE_SETTING_RANGES[field];
  const ok = Number.isFinite(value) && value >= min && value <= max;
  if (!ok || (integer && !Number.isInteger(value))) {
    const kind = integer ? 'an integer' : 'a number';
    throw new HalError(
      'RANGE_EXCEEDED',
      `calibration "${field}" must be ${kind} in ${min}..${max} ${unit}, got ${value}`,
      { details: { parameter: field, min, max, received: value } },
    );
  }
  return value;
}

/** The `set_config` parameters of `calibration`; RANGE_EXCEEDED naming the field and range. */
export function calibrationParams(calibration: WheelCalibration): CalibrationParams {
  const params: CalibrationParams = {
    wheel_diameter_cm: checked('wheel_diameter_cm', calibration.wheelDiameterCm),
    wheel_base_cm: checked('wheel_base_cm', calibration.wheelBaseCm),
  };
  if (calibration.stepsPerRevolution !== undefined) {
    params.steps_per_revolution = checked('steps_per_revolution', calibration.stepsPerRevolution);
  }
  return params;
}

function describe(params: CalibrationParams): string {
  return Object.entries(params)
    .map(([field, value]) => `${field}=${String(value)}`)
    .join(', ');
}

/**
 * Sends `calibration` with `send` (a `set_config`) and resolves the configuration the robot now
 * reports. A refusal keeps the robot's own code and names the values and the robot's reason; a
 * reply whose values differ from those sent is a HARDWARE_ERROR naming the field.
 */
export async function sendCalibration(
  send: (params: CalibrationParams) => Promise<SetConfigReply>,
  calibration: WheelCalibration,
  deviceId: string,
): Promise<DeviceConfig> {
  const params = calibrationParams(calibration);
  let reply: SetConfigReply;
  try {
    reply = await send(params);
  } catch (error) {
    if (!isHalError(error)) throw error;
    throw new HalError(
      error.code,
      `robot ${deviceId} did not take its calibration (${describe(params)}): ${error.message}`,
      { cause: error, ...(error.details === undefined ? {} : { details: error.details }) },
    );
  }
  for (const [field, sent] of Object.entries(params) as [keyof CalibrationParams, number][]) {
    const applied = reply.config[field];
    // the firmware writes numbers with 9 decimals: anything closer than a micrometre is the same
    if (applied === undefined || Math.abs(applied - sent) > 1e-6) {
      throw new HalError(
        'HARDWARE_ERROR',
        `robot ${deviceId} reports ${field}=${String(applied)} after set_config ${field}=${sent}`,
        { details: { parameter: field, sent, applied } },
      );
    }
  }
  return reply.config;
}
