import { HalErrorPayloadSchema } from '@hal/types';
import { z } from 'zod';

/*
 * The spec's payloads (docs/nats.md), each inside the Tafy envelope. Fields carry their units in
 * their names; readers ignore fields they do not know (loose objects).
 */

/** `motor.differential.cmd`: drive at a body velocity, optionally for a time. */
export const DifferentialCommandSchema = z.looseObject({
  linear_vel_m_per_s: z.number().describe('Forward speed, m/s (negative: backwards)'),
  angular_vel_rad_per_s: z.number().describe('Turn rate, rad/s, counter-clockwise positive'),
  duration_ms: z
    .number()
    .optional()
    .describe('Stop after this many ms; without it, drive until the next command or stop'),
  stop_action: z
    .enum(['brake', 'coast'])
    .optional()
    .describe('How to stop when duration_ms ends; both stop the steppers at once'),
});
export type DifferentialCommand = z.infer<typeof DifferentialCommandSchema>;

/** `motor.differential.state`, streamed at the gateway's state rate (10-100 Hz). */
export const DifferentialStateSchema = z.looseObject({
  left_vel_m_per_s: z.number().describe('Left wheel ground speed, m/s'),
  right_vel_m_per_s: z.number().describe('Right wheel ground speed, m/s'),
  linear_vel_m_per_s: z.number().describe('Body forward speed, m/s'),
  angular_vel_rad_per_s: z.number().describe('Body turn rate, rad/s'),
  x_m: z.number().describe('Pose x, metres (REP-103 world frame)'),
  y_m: z.number().describe('Pose y, metres'),
  yaw_rad: z.number().describe('Heading, radians, counter-clockwise positive'),
  emergency_stopped: z.boolean().describe('Whether the emergency stop is latched'),
  timestamp_ms: z.number().describe('When the state was read, ms since the Unix epoch'),
  battery_volts: z
    .number()
    .optional()
    .describe('Supply voltage, V; only where the robot measures it'),
  current_amps: z
    .number()
    .optional()
    .describe('Supply current, A; only where the robot measures it'),
});
export type DifferentialState = z.infer<typeof DifferentialStateSchema>;

const Xyz = z.looseObject({ x: z.number(), y: z.number(), z: z.number() });

/** A unit quaternion, the spec's `{w, x, y, z}` order. */
export const QuaternionSchema = z.looseObject({
  w: z.number(),
  x: z.number(),
  y: z.number(),
  z: z.number(),
});

/**
 * `sensor.imu.data`, streamed only by a device that offers an IMU. The spec's fields
 * (`orientation_quaternion`, `accel_m_per_s2`, `gyro_rad_per_s`, and `temperature_celsius`,
 * `mag_tesla` where the IMU has them: absent otherwise), and ours (`heading_rad`, `source`).
 */
export const ImuDataSchema = z.looseObject({
  orientation_quaternion: QuaternionSchema.describe('Orientation in the world frame (REP-103)'),
  accel_m_per_s2: Xyz.describe('Acceleration, m/s^2'),
  gyro_rad_per_s: Xyz.describe('Rotation rate, rad/s'),
  temperature_celsius: z.number().optional().describe('IMU temperature, where it has a sensor'),
  mag_tesla: Xyz.optional().describe('Magnetic field, tesla, where it has a magnetometer'),
  // ours, always sent by our gateway; optional so that a device speaking only the spec is valid
  heading_rad: z.number().optional().describe('Heading, radians (ours, beside the quaternion)'),
  source: z
    .string()
    .optional()
    .describe('Where the reading comes from: sensor, odometry, simulation (ours)'),
});
export type ImuData = z.infer<typeof ImuDataSchema>;

/**
 * `sensor.range.data`: the spec's one-sensor range message, one message per sensor each tick,
 * `sensor` naming it (`front`, `left`, `right`, `front_left`, `front_right`). Streamed only by a
 * device that offers range sensors.
 */
export const RangeDataSchema = z.looseObject({
  sensor: z.string().min(1).describe('Which sensor: front, left, right, front_left, front_right'),
  distance_m: z.number().describe('Distance to the nearest obstacle, metres'),
  min_range_m: z.number().describe('Shortest distance the sensor reads, metres'),
  max_range_m: z.number().describe('Longest distance; the reading when nothing is in range'),
  fov_deg: z.number().describe('Full field of view of the sensor, degrees'),
  confidence: z.number().min(0).max(1).describe('1: an obstacle in range; 0: nothing in range'),
  source: z.string().optional().describe('Where the reading comes from (ours)'),
});
export type RangeData = z.infer<typeof RangeDataSchema>;

/** `sensor.range.all` (ours, beside the spec's): every sensor in one message. */
export const RangeSummarySchema = z.looseObject({
  front_m: z.number().describe('Range ahead, metres'),
  left_m: z.number().describe('Range to the left, metres'),
  right_m: z.number().describe('Range to the right, metres'),
  source: z.string(),
});
export type RangeSummary = z.infer<typeof RangeSummarySchema>;

/** `camera.frame.req`; the reply is {@link CameraFrameSchema}. Size and quality are advisory. */
export const CameraFrameRequestSchema = z.looseObject({
  format: z.literal('jpeg').optional(),
  width: z.number().optional(),
  height: z.number().optional(),
  quality: z.number().optional(),
});

export const CameraFrameSchema = z.looseObject({
  format: z.literal('jpeg'),
  width: z.number().int().positive().describe('Image width, pixels (of the JPEG in data)'),
  height: z.number().int().positive().describe('Image height, pixels'),
  data: z.string().describe('Base64 JPEG bytes'),
  timestamp_ms: z.number(),
});
export type CameraFrame = z.infer<typeof CameraFrameSchema>;

/** `system.health.req`; the reply is {@link HealthSchema}. */
export const HealthRequestSchema = z.looseObject({ include_diagnostics: z.boolean().optional() });

export const HealthSchema = z.looseObject({
  status: z.enum(['healthy', 'degraded', 'emergency_stopped', 'not_ready']),
  uptime_s: z.number().describe('Seconds since the gateway started serving'),
  mode: z.string().describe('simulation, physical or hybrid'),
  free_memory_bytes: z
    .number()
    .nonnegative()
    .describe("Memory the serving process can still allocate, bytes (a gateway: its V8 heap's)"),
  cpu_percent: z
    .number()
    .nonnegative()
    .describe(
      'CPU time the serving process used, percent of one core, since the last health reply',
    ),
  battery_percent: z.number().optional(),
  temperature_celsius: z.number().optional(),
  diagnostics: z
    .looseObject({
      errors: z.array(z.string()),
      voltage: z.number().optional().describe('Supply voltage, V, where the robot measures it'),
    })
    .optional(),
});
export type Health = z.infer<typeof HealthSchema>;

/** `system.capability.announce` (published) and the reply to `system.capability.req`. */
export const CapabilityAnnouncementSchema = z.looseObject({
  device_type: z.string(),
  mode: z.string(),
  caps: z.array(z.string()),
  state_rate_hz: z.number(),
});
export type CapabilityAnnouncement = z.infer<typeof CapabilityAnnouncementSchema>;

/** The spec's error body, as a reply: `{ "error": { code, message, details } }`. */
export const ErrorReplySchema = z.looseObject({ error: HalErrorPayloadSchema });

/** An acknowledgement of a command sent with a reply inbox. */
export const AckSchema = z.looseObject({ ok: z.literal(true) });

/** `hal.call.req`: one call of the HAL contract, for NatsHAL. */
export const HalCallSchema = z.looseObject({
  request_id: z.string().min(1).max(128).describe('Unique per call; a retry repeats it'),
  call: z.string().describe('e.g. locomotion.moveTo'),
  args: z.array(z.unknown()),
});
export type HalCall = z.infer<typeof HalCallSchema>;

/** The reply to `hal.call.req`: a result, a value, or an error; plus the safety state after it. */
export const HalCallReplySchema = z.looseObject({
  request_id: z.string(),
  result: z.unknown().optional(),
  value: z.unknown().optional(),
  error: HalErrorPayloadSchema.optional(),
  emergency_stopped: z.boolean(),
  /** Why the served HAL is latched (as it stored the reason), while it is. */
  emergency_stop_reason: z.string().optional(),
});
export type HalCallReply = z.infer<typeof HalCallReplySchema>;

/** Schema names written into the envelope's `schema` field. */
export const SCHEMAS = Object.freeze({
  differentialCommand: 'hal/motor/differential/cmd/1.0',
  differentialState: 'hal/motor/differential/state/1.0',
  imu: 'hal/sensor/imu/data/1.0',
  range: 'hal/sensor/range/data/1.0',
  rangeSummary: 'hal/sensor/range/all/1.0',
  cameraRequest: 'hal/camera/frame/req/1.0',
  cameraFrame: 'hal/camera/frame/resp/1.0',
  healthRequest: 'hal/system/health/req/1.0',
  health: 'hal/system/health/resp/1.0',
  capabilities: 'hal/system/capability/1.0',
  estop: 'hal/safety/estop/cmd/1.0',
  heartbeat: 'hal/system/heartbeat/1.0',
  call: 'hal/hal/call/req/1.0',
  callReply: 'hal/hal/call/resp/1.0',
  ack: 'hal/ack/1.0',
  error: 'hal/error/1.0',
} as const);
