import { z } from 'zod';

/*
 * Zod schemas for every reply of protocol 1.1 (docs/protocol.md). Unknown fields are ignored
 * (stripped), `null` is treated as absent, and anything else that does not match is MALFORMED.
 */

const uint32 = z.number().int().min(0).max(4_294_967_295);
const int = z.number().int();
const finite = z.number();
/** An optional field: absent or `null` (both mean absent). */
const opt = <T extends z.ZodType>(schema: T) =>
  schema
    .nullish()
    .transform((value) => value ?? undefined)
    .optional();

/** The fields every reply carries. */
export const ReplyEnvelopeSchema = z.looseObject({
  seq: opt(uint32).describe('Echo of the request sequence number'),
  sid: opt(uint32).describe('Echo of the session id (hello: the new session id)'),
  ok: z.boolean().describe('Whether the command was executed'),
  cmd: opt(z.string()).describe('Echo of the command name'),
  error: opt(
    z.object({
      code: z.string().describe('Protocol error code'),
      message: z.string().describe('Names the field and the limit'),
      details: opt(z.record(z.string(), z.unknown())),
    }),
  ).describe('Present when ok is false'),
});
export type ReplyEnvelope = z.infer<typeof ReplyEnvelopeSchema>;

/**
 * The device configuration (`hello`, `set_config`): each field as the firmware writes it (the
 * `wireType` of its row in `ROBOT_SETTINGS`; steps/rev is a double the firmware keeps).
 */
export const DeviceConfigSchema = z.object({
  wheel_diameter_cm: finite,
  wheel_base_cm: finite,
  steps_per_revolution: finite,
  max_speed_steps_per_s: int,
  acceleration_steps_per_s2: int,
  host_timeout_ms: int,
  max_steps_per_command: opt(int),
});
export type DeviceConfig = z.infer<typeof DeviceConfigSchema>;

/** How a robot authenticates messages: `hmac-sha256` (a pre-shared key) or `none` (its opt-out). */
export type AuthScheme = 'none' | 'hmac-sha256';

/**
 * `hello`'s `auth`: protocol 1.1 names the scheme; a 1.0 robot said `true` (keyed) or `false`,
 * read here as the scheme it meant.
 */
export const AuthSchemeSchema = z
  .union([
    z.enum(['none', 'hmac-sha256']),
    z.boolean().transform((keyed): AuthScheme => (keyed ? 'hmac-sha256' : 'none')),
  ])
  .describe('How the robot authenticates messages: "hmac-sha256" (a key) or "none" (opt-out)');

export const HelloReplySchema = z.object({
  sid: uint32.refine((v) => v !== 0, 'sid must be non-zero'),
  nonce: opt(z.string()),
  device_id: z.string(),
  firmware_version: z.string(),
  protocol_version: z.string(),
  auth: AuthSchemeSchema,
  capabilities: z.array(z.string()),
  config: DeviceConfigSchema,
});
export type HelloReply = z.infer<typeof HelloReplySchema>;

export const HeartbeatReplySchema = z.object({
  uptime_ms: int,
  running: z.boolean(),
  estop: z.boolean(),
});
export type HeartbeatReply = z.infer<typeof HeartbeatReplySchema>;

/** Reply to `move_steps`, `move_cm`, `rotate_deg` and `drive`. */
export const MotionReplySchema = z.object({
  move_id: uint32,
  left_steps: opt(int),
  right_steps: opt(int),
  speed: opt(finite),
  speed_clamped: opt(z.boolean()),
  duration_ms: opt(int),
  duration_us: opt(int),
  left_sps: opt(finite),
  right_sps: opt(finite),
  running: opt(z.boolean()),
});
export type MotionReply = z.infer<typeof MotionReplySchema>;

/** The LED patterns of `set_led`. */
export const LED_PATTERNS = ['solid', 'blink', 'pulse', 'off'] as const;
export type LedPattern = (typeof LED_PATTERNS)[number];

export const LedStateSchema = z.object({
  r: int.min(0).max(255),
  g: int.min(0).max(255),
  b: int.min(0).max(255),
  pattern: z.string(),
});
export type LedState = z.infer<typeof LedStateSchema>;

export const MOVE_OUTCOMES = [
  'none',
  'running',
  'done',
  'stopped',
  'estop',
  'host_timeout',
  'replaced',
] as const;
export type MoveOutcome = (typeof MOVE_OUTCOMES)[number];

export const SafetyStateSchema = z.object({
  estop: z.boolean(),
  estop_reason: z.string(),
  trips: int,
  last_trip: opt(
    z.object({
      reason: z.string(),
      detail: z.string(),
      uptime_ms: int,
    }),
  ),
  host_timeout_ms: int,
  ms_since_host: int,
  coils_on: z.boolean(),
});
export type SafetyState = z.infer<typeof SafetyStateSchema>;

export const StatusReplySchema = z.object({
  x_cm: finite,
  y_cm: finite,
  heading_rad: finite,
  left_steps: int,
  right_steps: int,
  running: z.boolean(),
  move_id: uint32,
  move_outcome: z.enum(MOVE_OUTCOMES),
  move_left_steps: int,
  move_right_steps: int,
  left_sps: finite,
  right_sps: finite,
  uptime_ms: int,
  safety: SafetyStateSchema,
  led: LedStateSchema,
});
export type StatusReply = z.infer<typeof StatusReplySchema>;

export const SetConfigReplySchema = z.object({ config: DeviceConfigSchema });
export type SetConfigReply = z.infer<typeof SetConfigReplySchema>;

export const SetLedReplySchema = z.object({ led: LedStateSchema });
export type SetLedReply = z.infer<typeof SetLedReplySchema>;

/**
 * What a `stop` or `estop` reply tells since protocol 1.1 (absent from a 1.0 robot): the motion it
 * ended, and on the robot's clock when the wheels came to rest.
 */
export const StopReportSchema = z.object({
  move_id: opt(uint32),
  move_outcome: opt(z.enum(MOVE_OUTCOMES)),
  move_left_steps: opt(int),
  move_right_steps: opt(int),
  /** Absolute wheel positions after the stop, steps. */
  left_steps: opt(int),
  right_steps: opt(int),
  /** The robot's uptime when it handled this request, microseconds. */
  uptime_us: opt(int),
  /** The robot's uptime when the wheels last came to rest, microseconds. */
  stopped_us: opt(int),
});
export type StopReport = z.infer<typeof StopReportSchema>;

export const StopReplySchema = StopReportSchema.extend({
  stopped: z.boolean(),
  left_steps: int,
  right_steps: int,
});
export type StopReply = z.infer<typeof StopReplySchema>;

export const EstopReplySchema = StopReportSchema.extend({
  estop: z.literal(true),
  estop_reason: z.string(),
  /** The robot's uptime when the latch was set, microseconds (1.1). */
  estop_us: opt(int),
});
export type EstopReply = z.infer<typeof EstopReplySchema>;

export const ResetEstopReplySchema = z.object({
  estop: z.literal(false),
  was_estopped: z.boolean(),
});
export type ResetEstopReply = z.infer<typeof ResetEstopReplySchema>;

/** The schema of each command's successful reply data. */
export const REPLY_SCHEMAS = {
  hello: HelloReplySchema,
  heartbeat: HeartbeatReplySchema,
  move_steps: MotionReplySchema,
  move_cm: MotionReplySchema,
  rotate_deg: MotionReplySchema,
  drive: MotionReplySchema,
  stop: StopReplySchema,
  get_status: StatusReplySchema,
  set_config: SetConfigReplySchema,
  set_led: SetLedReplySchema,
  estop: EstopReplySchema,
  reset_estop: ResetEstopReplySchema,
} as const;

/** A command name of protocol 1.0. */
export type Command = keyof typeof REPLY_SCHEMAS;
/** The reply data of a command. */
export type ReplyOf<C extends Command> = z.output<(typeof REPLY_SCHEMAS)[C]>;
/** The reply data of a command as a device writes it (`null` allowed for absent fields). */
export type ReplyDataOf<C extends Command> = z.input<(typeof REPLY_SCHEMAS)[C]>;

/** Request parameters per command (H->D), beside `cmd`, `seq` and `sid`. */
export interface RequestParams {
  hello: { client?: string; nonce?: string };
  heartbeat: Record<string, never>;
  move_steps: { left: number; right: number; speed?: number };
  move_cm: { left_cm: number; right_cm: number; speed?: number };
  rotate_deg: { degrees: number; speed?: number };
  drive: { left_sps: number; right_sps: number; duration_ms?: number };
  stop: Record<string, never>;
  get_status: Record<string, never>;
  set_config: Partial<Omit<DeviceConfig, 'max_steps_per_command'>>;
  set_led: { r?: number; g?: number; b?: number; pattern?: LedPattern };
  estop: { reason?: string };
  reset_estop: Record<string, never>;
}
