// The messages of the remote HAL, shared by the server and the client. Every message is a Tafy
// envelope ({hal_major, hal_minor, schema, device_id, caps, ts, payload}); `schema` says which
// payload it carries. See docs/remote.md.
import {
  DeviceInfoSchema,
  EnvelopeSchema,
  HALModeSchema,
  HalError,
  HalErrorPayloadSchema,
  PoseSchema,
  SafetyStatusSchema,
  makeEnvelope,
  parseEnvelope,
} from '@hal/types';
import type { Envelope } from '@hal/types';
import { z } from 'zod';

/** The payload schema names, one per message kind. */
export const MESSAGE_SCHEMAS = {
  /** client -> server: run a HAL call. */
  call: 'hal.remote.call',
  /** client -> server: I am still here. */
  heartbeat: 'hal.remote.heartbeat',
  /** client -> server: make me the controller. */
  takeControl: 'hal.remote.take_control',
  /** client -> server: start or stop the state stream. */
  subscribe: 'hal.remote.subscribe',
  /** server -> client: who you are talking to, sent once on connection. */
  hello: 'hal.remote.hello',
  /** server -> client: the answer to a call (or to a message that could not be run). */
  reply: 'hal.remote.reply',
  /** server -> client: pose, motion and safety, at the stream rate. */
  state: 'hal.remote.state',
  /** server -> client: your role changed. */
  control: 'hal.remote.control',
} as const;

/** Most arguments any call takes, plus headroom. */
export const MAX_ARGS = 8;

const RequestId = z.string().min(1).max(64).describe('Chosen by the client, echoed in the reply');

export const CallPayloadSchema = z.looseObject({
  id: RequestId,
  call: z.string().min(1).max(64).describe('HAL call name, e.g. moveForward'),
  args: z.array(z.unknown()).max(MAX_ARGS).describe('Positional arguments (encodeArgs)'),
});
export type CallPayload = z.infer<typeof CallPayloadSchema>;

export const HeartbeatPayloadSchema = z.looseObject({});
export const TakeControlPayloadSchema = z.looseObject({ id: RequestId.optional() });
export const SubscribePayloadSchema = z.looseObject({
  state: z.boolean().describe('true: send state messages; false: stop'),
});

export const RoleSchema = z.enum(['controller', 'watcher']);
export type Role = z.infer<typeof RoleSchema>;

export const HelloPayloadSchema = z.looseObject({
  session_id: z.string(),
  role: RoleSchema,
  mode: HALModeSchema,
  device: DeviceInfoSchema,
  heartbeat_timeout_ms: z.number().positive(),
  state_rate_hz: z.number().positive(),
  max_message_bytes: z.number().int().positive(),
});
export type HelloPayload = z.infer<typeof HelloPayloadSchema>;

export const ReplyPayloadSchema = z.discriminatedUnion('ok', [
  z.looseObject({
    id: z.string().nullable(),
    ok: z.literal(true),
    value: z.unknown(),
    safety: SafetyStatusSchema,
  }),
  z.looseObject({
    id: z.string().nullable().describe('null when the message had no readable id'),
    ok: z.literal(false),
    error: HalErrorPayloadSchema,
    safety: SafetyStatusSchema,
  }),
]);
export type ReplyPayload = z.infer<typeof ReplyPayloadSchema>;

export const StatePayloadSchema = z.looseObject({
  pose: PoseSchema.nullable().describe(
    'REP-103 pose (metres, radians, m/s, rad/s); null if unread',
  ),
  moving: z.boolean().describe('A motion call is running on the server'),
  safety: SafetyStatusSchema,
  role: RoleSchema,
});
export type StatePayload = z.infer<typeof StatePayloadSchema>;

export const ControlPayloadSchema = z.looseObject({
  role: RoleSchema,
  reason: z.string(),
});
export type ControlPayload = z.infer<typeof ControlPayloadSchema>;

const PAYLOADS = {
  [MESSAGE_SCHEMAS.call]: CallPayloadSchema,
  [MESSAGE_SCHEMAS.heartbeat]: HeartbeatPayloadSchema,
  [MESSAGE_SCHEMAS.takeControl]: TakeControlPayloadSchema,
  [MESSAGE_SCHEMAS.subscribe]: SubscribePayloadSchema,
  [MESSAGE_SCHEMAS.hello]: HelloPayloadSchema,
  [MESSAGE_SCHEMAS.reply]: ReplyPayloadSchema,
  [MESSAGE_SCHEMAS.state]: StatePayloadSchema,
  [MESSAGE_SCHEMAS.control]: ControlPayloadSchema,
} as const;
type Payloads = typeof PAYLOADS;
export type MessageSchema = keyof Payloads;

/** A decoded message: its schema name and checked payload. */
export type Message = {
  [K in MessageSchema]: { schema: K; envelope: Envelope<z.output<Payloads[K]>> };
}[MessageSchema];

/**
 * Parses one text frame into a message. Throws a HalError: MALFORMED for text that is not JSON,
 * not an envelope, of an unknown schema, or whose payload does not match its schema.
 */
export function decodeMessage(text: string): Message {
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch {
    throw new HalError('MALFORMED', 'message is not JSON');
  }
  const envelope = EnvelopeSchema.safeParse(raw);
  if (!envelope.success) {
    throw new HalError(
      'MALFORMED',
      `not a HAL envelope: ${envelope.error.issues[0]?.message ?? 'invalid'}`,
    );
  }
  const schema = envelope.data.schema;
  if (!Object.hasOwn(PAYLOADS, schema)) {
    throw new HalError('MALFORMED', `unknown message schema "${schema}"`, {
      details: { schema },
    });
  }
  const name = schema as MessageSchema;
  return { schema: name, envelope: parseEnvelope(raw, PAYLOADS[name]) } as Message;
}

/** Wraps a payload in an envelope and serialises it. */
export function encodeMessage<K extends MessageSchema>(
  schema: K,
  sender: { deviceId: string; caps?: readonly string[] },
  payload: z.input<Payloads[K]>,
): string {
  return JSON.stringify(
    makeEnvelope({ schema, device_id: sender.deviceId, caps: sender.caps ?? [] }, payload),
  );
}

/** The id of a message that failed to decode, if one can be read, so the error reply names it. */
export function readRequestId(text: string): string | null {
  try {
    const raw: unknown = JSON.parse(text);
    const id = (raw as { payload?: { id?: unknown } } | null)?.payload?.id;
    return typeof id === 'string' && id.length > 0 && id.length <= 64 ? id : null;
  } catch {
    return null;
  }
}

// JSON has no NaN, Infinity or undefined; a remote call must reach the HAL exactly as a local one
// would (so a NaN is refused by the HAL's own validation, naming the parameter), so they travel
// tagged.
const SPECIAL = z.union([
  z.strictObject({ $number: z.enum(['NaN', 'Infinity', '-Infinity']) }),
  z.strictObject({ $undefined: z.literal(true) }),
]);

/** Encodes call arguments for the wire: NaN, +-Infinity and undefined are tagged. */
export function encodeArgs(args: readonly unknown[]): unknown[] {
  const out = args.map((arg) => {
    if (arg === undefined) return { $undefined: true };
    if (typeof arg === 'number' && !Number.isFinite(arg)) return { $number: String(arg) };
    return arg;
  });
  while (out.length > 0 && isUndefinedTag(out[out.length - 1])) out.pop();
  return out;
}

function isUndefinedTag(value: unknown): boolean {
  return typeof value === 'object' && value !== null && '$undefined' in value;
}

/** Decodes call arguments from the wire (the inverse of {@link encodeArgs}). */
export function decodeArgs(args: readonly unknown[]): unknown[] {
  return args.map((arg) => {
    // only an object can be a special value: the common case skips the schema (and its issues)
    if (typeof arg !== 'object' || arg === null) return arg;
    const special = SPECIAL.safeParse(arg);
    if (!special.success) return arg;
    return '$number' in special.data ? Number(special.data.$number) : undefined;
  });
}
