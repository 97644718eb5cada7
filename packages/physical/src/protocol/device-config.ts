import { FIRMWARE_SETTINGS } from '@hal/kinematics';
import { robotConfig, V1_ROBOT } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { DeviceConfig } from './schemas.js';

/**
 * The most steps one wheel may make in one command: fixed in the firmware, reported by `hello`
 * (protocol 1.1 section 5.1); the settings table's `maxStepsPerCommand` default.
 */
export const MAX_STEPS_PER_COMMAND = V1_ROBOT.maxStepsPerCommand;

/** The configuration `set_config` may change: every {@link DeviceConfig} field but the fixed limit. */
export type DeviceSettings = Omit<DeviceConfig, 'max_steps_per_command'>;

/** A `set_config` field's accepted range (inclusive, as the firmware checks it). */
export interface SettingRange {
  min: number;
  max: number;
  integer: boolean;
  unit: string;
}

/**
 * Every field `set_config` takes and its range, by its wire name: the firmware's ranges
 * (cube_commands.cpp), as `@hal/kinematics`' robot model holds them (`FIRMWARE_SETTINGS`).
 */
export const DEVICE_SETTING_RANGES: Readonly<Record<keyof DeviceSettings, SettingRange>> =
  Object.freeze(
    Object.fromEntries(
      FIRMWARE_SETTINGS.map(({ field, min, max, integer, unit }) => [
        field,
        { min, max, integer, unit },
      ]),
    ) as Record<keyof DeviceSettings, SettingRange>,
  );

/** The wheel geometry of a device configuration, as the step math (`@hal/kinematics`) takes it. */
export function deviceGeometry(
  c: DeviceSettings,
): Pick<RobotConfig, 'stepsPerRevolution' | 'wheelDiameterCm' | 'wheelBaseCm'> {
  return {
    stepsPerRevolution: c.steps_per_revolution,
    wheelDiameterCm: c.wheel_diameter_cm,
    wheelBaseCm: c.wheel_base_cm,
  };
}

/**
 * The robot configuration a device reports (`hello`, `set_config`), over `base` for the fields
 * the protocol does not carry.
 */
export function robotConfigFromDevice(base: RobotConfig, c: DeviceConfig): RobotConfig {
  const reported = Object.fromEntries(
    FIRMWARE_SETTINGS.map(({ key, field }) => [key, c[field as keyof DeviceSettings]]),
  );
  return robotConfig({
    ...base,
    ...reported,
    maxStepsPerCommand: Math.min(
      base.maxStepsPerCommand,
      c.max_steps_per_command ?? MAX_STEPS_PER_COMMAND,
    ),
  });
}

/**
 * The device settings of a robot configuration, from the settings table: every field `set_config`
 * sets, in the order the firmware writes them. Each is a JSON number, as the firmware writes it
 * (`steps_per_revolution` is a double there, written without a fraction when it has none).
 */
export function deviceSettingsOf(robot: RobotConfig): DeviceSettings {
  return Object.fromEntries(
    FIRMWARE_SETTINGS.map(({ key, field }) => [field, robot[key]]),
  ) as DeviceSettings;
}
