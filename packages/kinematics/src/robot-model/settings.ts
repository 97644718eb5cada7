import { HalError, RobotConfigSchema } from '@hal/types';
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
  /** The robot's value at boot. */
  default: number;
  /** How the firmware writes it in its `config` reply (`double`: a double, no fraction when whole). */
  wireType: 'int' | 'double';
}

/**
 * Every field `set_config` takes, read from the one settings table (`ROBOT_SETTINGS` in
 * `@hal/types`, which `RobotConfigSchema` is built from and carries as each field's metadata):
 * the rows `set_config` sets, in the order the firmware writes them.
 */
function firmwareSettings(): FirmwareSetting[] {
  const rows: FirmwareSetting[] = [];
  for (const [key, field] of Object.entries(RobotConfigSchema.shape)) {
    const meta = field.meta();
    if (meta?.['setBy'] !== 'set_config') continue;
    const { wire, unit, wireType } = meta;
    const number = field.unwrap();
    const { minValue, maxValue } = number;
    if (
      typeof wire !== 'string' ||
      typeof unit !== 'string' ||
      (wireType !== 'int' && wireType !== 'double') ||
      minValue === null ||
      maxValue === null
    ) {
      throw new TypeError(`the settings table's row "${key}" lacks its wire name, unit or range`);
    }
    rows.push({
      key: key as FirmwareSettingKey,
      field: wire,
      min: minValue,
      max: maxValue,
      integer: number.isInt,
      unit,
      default: field.def.defaultValue,
      wireType,
    });
  }
  return rows;
}

/** Every field `set_config` takes and its range, as the firmware (cube_commands.cpp) checks it. */
export const FIRMWARE_SETTINGS: readonly FirmwareSetting[] = Object.freeze(firmwareSettings());

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
