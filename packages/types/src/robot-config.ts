import { z } from 'zod';
import { CameraModelSchema } from './camera-model.js';

/**
 * The robot's geometry and the limits every layer enforces. Defaults are the V1 stepper cube:
 * 28BYJ-48 steppers (4096 half-steps per revolution), 6 cm wheels, 10 cm wheel base.
 * Every limit the validation layer applies is read from here, never from a literal elsewhere.
 */
export const RobotConfigSchema = z.object({
  stepsPerRevolution: z
    .number()
    .int()
    .min(1)
    .max(1_000_000)
    .default(4096)
    .describe(
      'Motor steps per wheel revolution (28BYJ-48 half-step: 4096 nominal, ~4076 measured)',
    ),
  wheelDiameterCm: z.number().gt(0).max(100).default(6).describe('Wheel diameter, cm'),
  wheelBaseCm: z
    .number()
    .gt(0)
    .max(200)
    .default(10)
    .describe('Distance between the wheel contact points, cm'),
  maxSpeedStepsPerS: z
    .number()
    .int()
    .min(1)
    .max(2048)
    .default(1024)
    .describe('Top wheel speed, steps/s (1..2048); the firmware clamps every command to it'),
  minSpeedStepsPerS: z
    .number()
    .int()
    .min(1)
    .max(2048)
    .default(64)
    .describe(
      'Slowest cruise speed a call may ask for, steps/s (1..2048, never above the top speed); ' +
        'slower requests are refused rather than run for hours',
    ),
  accelerationStepsPerS2: z
    .number()
    .int()
    .min(1)
    .max(100_000)
    .default(512)
    .describe('Wheel acceleration of the trapezoidal profile, steps/s^2'),
  maxStepsPerCommand: z
    .number()
    .int()
    .min(1)
    .max(40_960)
    .default(40_960)
    .describe('Most steps one wheel may make in one command; the firmware refuses more'),
  hostTimeoutMs: z
    .number()
    .int()
    .min(500)
    .max(10_000)
    .default(2000)
    .describe(
      'Motors stop when the robot hears nothing from its host for this long, ms (500..10000)',
    ),
  maxDriveDurationMs: z
    .number()
    .int()
    .min(1)
    .max(600_000)
    .default(60_000)
    .describe('Longest duration one drive() call may ask for, ms'),
  workspaceHalfExtentM: z
    .number()
    .gt(0)
    .max(1000)
    .default(50)
    .describe('moveTo targets must lie within +/- this many metres of the origin on x and y'),
});

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
