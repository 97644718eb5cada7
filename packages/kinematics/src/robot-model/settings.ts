import { HalError } from '@hal/types';
import type { RobotConfig } from '@hal/types';

/** The fields of the robot's configuration that `set_config` changes on the robot. */
export type FirmwareSettingKey =
  | 'wheelDiameterCm'
  | 'wheelBaseCm'
  | 'stepsPerRevolution'
  | 'maxSpeedStepsPerS'
  | 'accelerationStepsPerS2'
  | 'hostTimeoutMs';

/** A `set_config` field's accepted range (inclusive, as the firmware checks it). */
export interface FirmwareSetting {
  key: FirmwareSettingKey;
  /** Its name on the wire (protocol section 5). */
  field: string;
  min: number;
  max: number;
  integer: boolean;
  unit: string;
}

/** Every field `set_config` takes and its range, as the firmware (cube_commands.cpp) checks it. */
export const FIRMWARE_SETTINGS: readonly FirmwareSetting[] = Object.freeze([
  {
    key: 'wheelDiameterCm',
    field: 'wheel_diameter_cm',
    min: 0.5,
    max: 50,
    integer: false,
    unit: 'cm',
  },
  { key: 'wheelBaseCm', field: 'wheel_base_cm', min: 1, max: 100, integer: false, unit: 'cm' },
  {
    key: 'stepsPerRevolution',
    field: 'steps_per_revolution',
    min: 100,
    max: 100_000,
    integer: true,
    unit: 'steps',
  },
  {
    key: 'maxSpeedStepsPerS',
    field: 'max_speed_steps_per_s',
    min: 1,
    max: 2048,
    integer: true,
    unit: 'steps/s',
  },
  {
    key: 'accelerationStepsPerS2',
    field: 'acceleration_steps_per_s2',
    min: 1,
    max: 100_000,
    integer: true,
    unit: 'steps/s^2',
  },
  {
    key: 'hostTimeoutMs',
    field: 'host_timeout_ms',
    min: 500,
    max: 10_000,
    integer: true,
    unit: 'ms',
  },
]);

/**
 * Throws unless `value` is what the robot takes for `setting`: INVALID_PARAMETER for a
 * non-finite number (or a fraction where it counts whole units), RANGE_EXCEEDED outside the
 * range. `label` is the name the caller knows the field by (default its configuration key).
 */
export function checkSetting(
  setting: FirmwareSetting,
  value: number,
  label: string = setting.key,
): void {
  const { min, max, integer, unit } = setting;
  if (
    typeof value !== 'number' ||
    !Number.isFinite(value) ||
    (integer && !Number.isInteger(value))
  ) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${label}" must be ${integer ? 'an integer' : 'a finite number'}, got ${value}`,
      { details: { field: label, value: String(value) } },
    );
  }
  if (value < min || value > max) {
    throw new HalError(
      'RANGE_EXCEEDED',
      `"${label}" must be ${min}..${max} ${unit}, got ${value}`,
      {
        details: { field: label, min, max, value },
      },
    );
  }
}

/** Checks every firmware setting present in `overrides` (the others are not the robot's). */
export function checkSettings(overrides: Partial<RobotConfig>): void {
  for (const setting of FIRMWARE_SETTINGS) {
    const value = overrides[setting.key];
    if (value !== undefined) checkSetting(setting, value);
  }
}
