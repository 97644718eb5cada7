/**
 * The robot's settings and configuration wire fields, written once. `RobotConfigSchema` is built
 * from this table, `@hal/kinematics`' `FIRMWARE_SETTINGS` (the ranges `set_config` checks) and
 * `@hal/physical`'s config reply are read from it, and a test holds the firmware's C++ (its
 * `settings.h` and defaults), tests/vectors/settings.json and the docs' tables to it.
 *
 * The ranges of the fields the robot keeps are the firmware's (its settings.h): the robot is
 * what enforces them, so the host refuses what the robot would.
 *
 * To add a setting: a row here (a host-only limit needs nothing else). One the robot keeps also
 * needs its row in the firmware's settings.h, its boot value in `CubeConfig`, its read in
 * `CmdSetConfig` and its write in `WriteConfigFields`, its name in vectors_test.cpp's `BootValue`
 * and settings-table.test.ts' C++ names, its field in `@hal/physical`'s `DeviceConfigSchema`, and
 * its row in docs/protocol.md section 5.10; then regenerate tests/vectors/settings.json
 * (tests/vectors/settings-vectors.ts). The tests name whatever is missing.
 */

/**
 * How a value reaches the robot: `set_config` changes it (and `hello` reports it); `hello` only
 * reports it (fixed in the firmware; the host adopts it); `none` means the host alone keeps it.
 */
export type SettingCommand = 'set_config' | 'hello' | 'none';

/** One row of {@link ROBOT_SETTINGS}. */
export interface RobotSetting {
  /** Its name in the host's robot configuration (`RobotConfig`). */
  readonly key: string;
  /** Its name in the robot's `config` object (hello, set_config), or null for a host-only limit. */
  readonly wire: string | null;
  readonly unit: string;
  readonly default: number;
  readonly min: number;
  /** True when `min` itself is refused (the value must be above it). */
  readonly minExclusive: boolean;
  /** The largest value taken (always inclusive). */
  readonly max: number;
  /** Whole numbers only (what `set_config` and the host schema take). */
  readonly integer: boolean;
  /**
   * How the firmware writes it in its `config` reply: `int` or `double` (a double the firmware
   * keeps, written without a fraction when it has none); null when it is not on the wire.
   */
  readonly wireType: 'int' | 'double' | null;
  readonly setBy: SettingCommand;
  /** What it is; the schema's description adds the range and unit. */
  readonly description: string;
}

/** The top wheel speed `set_config` takes, steps/s (the firmware's `kMaxSpeedStepsPerS.max`). */
const SPEED_CEILING_STEPS_PER_S = 2048;

/** Every setting of the robot, in the order the firmware writes its `config` object. */
export const ROBOT_SETTINGS = Object.freeze([
  {
    key: 'wheelDiameterCm',
    wire: 'wheel_diameter_cm',
    unit: 'cm',
    default: 6,
    min: 0.5,
    minExclusive: false,
    max: 50,
    integer: false,
    wireType: 'double',
    setBy: 'set_config',
    description: 'Wheel diameter',
  },
  {
    key: 'wheelBaseCm',
    wire: 'wheel_base_cm',
    unit: 'cm',
    default: 10,
    min: 1,
    minExclusive: false,
    max: 100,
    integer: false,
    wireType: 'double',
    setBy: 'set_config',
    description: 'Distance between the wheel contact points',
  },
  {
    key: 'stepsPerRevolution',
    wire: 'steps_per_revolution',
    unit: 'steps',
    default: 4096,
    min: 100,
    minExclusive: false,
    max: 100_000,
    integer: true,
    // set_config takes whole steps; the firmware keeps (and reports) a double
    wireType: 'double',
    setBy: 'set_config',
    description:
      'Motor steps per wheel revolution (28BYJ-48 half-step: 4096 nominal, ~4076 measured)',
  },
  {
    key: 'maxSpeedStepsPerS',
    wire: 'max_speed_steps_per_s',
    unit: 'steps/s',
    default: 1024,
    min: 1,
    minExclusive: false,
    max: SPEED_CEILING_STEPS_PER_S,
    integer: true,
    wireType: 'int',
    setBy: 'set_config',
    description: 'Top wheel speed; the firmware clamps every command to it',
  },
  {
    key: 'accelerationStepsPerS2',
    wire: 'acceleration_steps_per_s2',
    unit: 'steps/s^2',
    default: 512,
    min: 1,
    minExclusive: false,
    max: 100_000,
    integer: true,
    wireType: 'int',
    setBy: 'set_config',
    description: 'Wheel acceleration of the trapezoidal profile',
  },
  {
    key: 'hostTimeoutMs',
    wire: 'host_timeout_ms',
    unit: 'ms',
    default: 2000,
    min: 500,
    minExclusive: false,
    max: 10_000,
    integer: true,
    wireType: 'int',
    setBy: 'set_config',
    description: 'Motors stop when the robot hears nothing from its host for this long',
  },
  {
    key: 'maxStepsPerCommand',
    wire: 'max_steps_per_command',
    unit: 'steps',
    default: 40_960,
    min: 1,
    minExclusive: false,
    max: 40_960,
    integer: true,
    wireType: 'int',
    setBy: 'hello',
    description:
      'Most steps one wheel may make in one command; the firmware refuses more (its own limit, reported by hello)',
  },
  {
    key: 'minSpeedStepsPerS',
    wire: null,
    unit: 'steps/s',
    default: 64,
    min: 1,
    minExclusive: false,
    max: SPEED_CEILING_STEPS_PER_S,
    integer: true,
    wireType: null,
    setBy: 'none',
    description:
      'Slowest cruise speed a call may ask for (never above the top speed); ' +
      'slower requests are refused rather than run for hours',
  },
  {
    key: 'maxDriveDurationMs',
    wire: null,
    unit: 'ms',
    default: 60_000,
    min: 1,
    minExclusive: false,
    max: 600_000,
    integer: true,
    wireType: null,
    setBy: 'none',
    description: 'Longest duration one drive() call may ask for',
  },
  {
    key: 'workspaceHalfExtentM',
    wire: null,
    unit: 'm',
    default: 50,
    min: 0,
    minExclusive: true,
    max: 1000,
    integer: false,
    wireType: null,
    setBy: 'none',
    description: 'moveTo targets must lie within +/- this many metres of the origin on x and y',
  },
] as const satisfies readonly RobotSetting[]);

/** The name of a setting in the host's robot configuration. */
export type RobotSettingKey = (typeof ROBOT_SETTINGS)[number]['key'];

/** A setting's range as the docs and error messages write it: `0.5..50`, `(0, 1000]`. */
export function settingRangeText(s: Pick<RobotSetting, 'min' | 'max' | 'minExclusive'>): string {
  return s.minExclusive ? `(${s.min}, ${s.max}]` : `${s.min}..${s.max}`;
}
