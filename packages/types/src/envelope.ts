import { z } from 'zod';
import { HalError } from './errors.js';

/** The HAL message-format version this library speaks. */
export const HAL_MAJOR = 1;
export const HAL_MINOR = 0;

/** The standard error shape inside messages that leave the process. Unknown fields are kept. */
export const HalErrorPayloadSchema = z
  .looseObject({
    code: z.string().min(1).describe('Machine-readable reason, e.g. RANGE_EXCEEDED'),
    message: z.string().describe('Human-readable reason'),
    details: z.record(z.string(), z.unknown()).optional().describe('Structured facts'),
  })
  .describe('Standard error');
export type HalErrorPayload = z.infer<typeof HalErrorPayloadSchema>;

const DEVICE_ID = /^[A-Za-z0-9_-]+$/;
const TOKEN = /^[a-z][a-z0-9_]*$/;

/**
 * The Tafy message envelope for messages that leave the process (NATS, WebSocket, logs). Readers
 * ignore fields they do not know; payload fields carry their units in their names.
 */
export const EnvelopeSchema = z
  .looseObject({
    hal_major: z.number().int().nonnegative().describe('Major version of the message format'),
    hal_minor: z.number().int().nonnegative().describe('Minor version of the message format'),
    schema: z.string().min(1).describe('Payload schema name, e.g. hal.locomotion.pose'),
    device_id: z.string().regex(DEVICE_ID).describe('Sending or addressed robot'),
    caps: z.array(z.string()).describe('Capability strings of the device'),
    ts: z.number().describe('Time the message was made, ms since the Unix epoch'),
    payload: z.unknown().describe('The message body'),
  })
  .describe('HAL message envelope');
export type Envelope<P = unknown> = Omit<z.infer<typeof EnvelopeSchema>, 'payload'> & {
  payload: P;
};

/** Wraps a payload in an envelope of this library's version. */
export function makeEnvelope<P>(
  init: { schema: string; device_id: string; caps?: readonly string[]; ts?: number },
  payload: P,
): Envelope<P> {
  if (!DEVICE_ID.test(init.device_id)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"device_id" must use letters, digits, "-" and "_", got "${init.device_id}"`,
    );
  }
  return {
    hal_major: HAL_MAJOR,
    hal_minor: HAL_MINOR,
    schema: init.schema,
    device_id: init.device_id,
    caps: [...(init.caps ?? [])],
    ts: init.ts ?? Date.now(),
    payload,
  };
}

/** Parses an envelope, checking its payload with `payload`; a newer major version is refused. */
export function parseEnvelope<S extends z.ZodType>(
  raw: unknown,
  payload: S,
): Envelope<z.output<S>> {
  const envelope = EnvelopeSchema.safeParse(raw);
  if (!envelope.success) {
    throw new HalError(
      'MALFORMED',
      `not a HAL envelope: ${envelope.error.issues[0]?.message ?? 'invalid'}`,
    );
  }
  if (envelope.data.hal_major !== HAL_MAJOR) {
    throw new HalError(
      'MALFORMED',
      `envelope is hal_major ${envelope.data.hal_major}; this library speaks ${HAL_MAJOR}`,
    );
  }
  const body = payload.safeParse(envelope.data.payload);
  if (!body.success) {
    throw new HalError(
      'MALFORMED',
      `envelope payload does not match "${envelope.data.schema}": ${body.error.issues[0]?.message ?? 'invalid'}`,
    );
  }
  return { ...envelope.data, payload: body.data };
}

/** The parts of a subject: `hal.v{major}.{device}.{domain}.{type}.{action}`. */
export interface SubjectParts {
  /** The addressed robot, or `*` (one level) / omitted with `>` as action for subscriptions. */
  device: string;
  domain: string;
  type: string;
  action: string;
  major?: number;
}

function subjectToken(name: string, value: string, allowWildcard: boolean): string {
  if (allowWildcard && (value === '*' || value === '>')) return value;
  const ok = name === 'device' ? DEVICE_ID.test(value) : TOKEN.test(value);
  if (!ok)
    throw new HalError('INVALID_PARAMETER', `subject "${name}" token is invalid: "${value}"`);
  return value;
}

/**
 * Builds a subject. One addressing scheme: the device id comes right after the version, so
 * `hal.v1.cube-01.>` is everything about one robot and `hal.v1.*.safety.estop.*` one thing about all.
 */
export function buildSubject(parts: SubjectParts, options: { wildcards?: boolean } = {}): string {
  const wild = options.wildcards ?? false;
  const major = parts.major ?? HAL_MAJOR;
  const tokens = [
    subjectToken('device', parts.device, wild),
    subjectToken('domain', parts.domain, wild),
    subjectToken('type', parts.type, wild),
    subjectToken('action', parts.action, wild),
  ];
  const gt = tokens.indexOf('>');
  if (gt >= 0 && gt !== tokens.length - 1) {
    throw new HalError('INVALID_PARAMETER', 'subject wildcard ">" may only be last');
  }
  return `hal.v${major}.${tokens.join('.')}`;
}

/** Splits a concrete subject into its parts; throws INVALID_PARAMETER if it is not one of ours. */
export function parseSubject(subject: string): Required<SubjectParts> {
  const tokens = subject.split('.');
  const match = /^v(\d+)$/.exec(tokens[1] ?? '');
  if (tokens.length !== 6 || tokens[0] !== 'hal' || match === null) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${subject}" is not a hal.v{major}.{device}.{domain}.{type}.{action} subject`,
    );
  }
  const [, , device = '', domain = '', type = '', action = ''] = tokens;
  const parts = { device, domain, type, action, major: Number(match[1]) };
  buildSubject(parts);
  return parts;
}
