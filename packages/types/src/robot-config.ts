import { z } from 'zod';
import { CameraModelSchema } from './camera-model.js';
import { ROBOT_SETTINGS, settingRangeText } from './robot-settings.js';
import type { RobotSetting, RobotSettingKey } from './robot-settings.js';

export { ROBOT_SETTINGS, settingRangeText } from './robot-settings.js';
export type { RobotSetting, RobotSettingKey, SettingCommand } from './robot-settings.js';

/**
 * A setting's schema: its row's range, whole numbers or not and default; its description, wire
 * name, unit, wire type, command and whether `min` is excluded are the schema's metadata
 * (`.meta()`): with the range, the whole row, which is how other packages read the table.
 */
function settingSchema(s: RobotSetting) {
  let n = z.number();
  if (s.integer) n = n.int();
  n = s.minExclusive ? n.gt(s.min) : n.min(s.min);
  return n
    .max(s.max)
    .default(s.default)
    .meta({
      description: `${s.description}. Range ${settingRangeText(s)} ${s.unit}`,
      wire: s.wire,
      unit: s.unit,
      minExclusive: s.minExclusive,
      wireType: s.wireType,
      setBy: s.setBy,
    });
}

/**
 * The robot's geometry and the limits every layer enforces, built from {@link ROBOT_SETTINGS}
 * (ranges, defaults, descriptions). Defaults are the V1 stepper cube: 28BYJ-48 steppers (4096
 * half-steps per revolution), 6 cm wheels, 10 cm wheel base. Every limit the validation layer
 * applies is read from here, never from a literal elsewhere.
 */
export const RobotConfigSchema = z.object(
  Object.fromEntries(ROBOT_SETTINGS.map((s) => [s.key, settingSchema(s)])) as {
    [K in RobotSettingKey]: ReturnType<typeof settingSchema>;
  },
);

/** The robot's geometry and limits (see {@link RobotConfigSchema}). */
export type RobotConfig = z.infer<typeof RobotConfigSchema>;

/** The V1 stepper cube. */
export const V1_ROBOT: RobotConfig = Object.freeze(RobotConfigSchema.parse({}));

/** Builds a full robot configuration from overrides, checking every field. */
export function robotConfig(overrides: Partial<RobotConfig> = {}): RobotConfig {
  return RobotConfigSchema.parse({ ...V1_ROBOT, ...overrides });
}

/** Motor steps per centimetre of wheel travel. */
export function stepsPerCm(config: RobotConfig): number {
  return config.stepsPerRevolution / (Math.PI * config.wheelDiameterCm);
}

/** The longest straight move one command allows, cm. */
export function maxDistancePerCommandCm(config: RobotConfig): number {
  return config.maxStepsPerCommand / stepsPerCm(config);
}

/** The largest in-place turn one command allows, degrees. */
export function maxRotationPerCommandDeg(config: RobotConfig): number {
  return (maxDistancePerCommandCm(config) * 360) / (Math.PI * config.wheelBaseCm);
}

/** Top linear speed, m/s. */
export function maxLinearSpeedMPerS(config: RobotConfig): number {
  return config.maxSpeedStepsPerS / stepsPerCm(config) / 100;
}

/**
 * Slowest cruise speed a call may ask for, m/s: `minSpeedStepsPerS` (never above the top speed)
 * along the ground. At the V1 default of 64 steps/s that is about 2.9 mm/s, so the longest single
 * command (40960 steps) takes at most about 11 minutes.
 */
export function minLinearSpeedMPerS(config: RobotConfig): number {
  const steps = Math.min(config.minSpeedStepsPerS, config.maxSpeedStepsPerS);
  return steps / stepsPerCm(config) / 100;
}

/** The links a HAL can reach a physical robot over; each has a transport in @hal/physical. */
export const CONNECTION_TYPES = ['serial', 'wifi'] as const;

/** How a HAL reaches a physical robot. */
export const ConnectionConfigSchema = z.object({
  type: z
    .enum(CONNECTION_TYPES, {
      error: (issue) =>
        `connection.type must be one of ${CONNECTION_TYPES.map((t) => `"${t}"`).join(', ')} ` +
        `(the links with a transport), got ${JSON.stringify(issue.input) ?? 'nothing'}`,
    })
    .describe('Link to the robot: "serial" (CRC-16 framed) or "wifi" (UDP)'),
  port: z.string().min(1).optional().describe('Serial device path, e.g. /dev/ttyUSB0'),
  baudRate: z.number().int().positive().optional().describe('Serial baud rate, bits/s'),
  host: z.string().min(1).optional().describe('Robot IP address or host name (wifi)'),
  udpPort: z
    .number()
    .int()
    .min(1)
    .max(65_535)
    .optional()
    .describe('Robot UDP port (wifi), default 4210'),
  cameraUrl: z.string().url().optional().describe('ESP32-CAM base URL, e.g. http://192.168.4.2'),
  cameraToken: z
    .string()
    .regex(/^[A-Za-z0-9._~-]{1,128}$/, 'up to 128 of A-Z a-z 0-9 - . _ ~')
    .optional()
    .describe('The ESP32-CAM token (its CAM_TOKEN), sent as "Authorization: Bearer"'),
  key: z
    .string()
    .regex(/^([0-9a-fA-F]{2})+$/)
    .optional()
    .describe('Pre-shared authentication key, hex'),
});
export type ConnectionConfig = z.infer<typeof ConnectionConfigSchema>;

/** Configuration for creating a HAL instance. */
export const HALConfigSchema = z.object({
  mode: z.enum(['simulation', 'physical', 'hybrid']),
  deviceId: z
    .string()
    .regex(/^[A-Za-z0-9_-]+$/, 'device ids use letters, digits, "-" and "_"')
    .describe('Unique robot id, also its address in message subjects'),
  connection: ConnectionConfigSchema.optional(),
  simulator: z.unknown().optional().describe('Simulation mode: the world or simulator to bind to'),
  capabilities: z.array(z.string()).optional().describe('Capability strings to enable'),
  robot: RobotConfigSchema.partial()
    .optional()
    .describe('Geometry and limits, default the V1 robot'),
  camera: CameraModelSchema.partial()
    .optional()
    .describe(
      "The camera's model where it differs from V1's (its calibration wins where it has one); " +
        'used only when the robot has a camera (connection.cameraUrl)',
    ),
});

/** Configuration for creating a HAL instance. */
export type HALConfig = z.infer<typeof HALConfigSchema>;
