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
    device_id: z.string().regex(DEVICE_ID).describe('The sender: the robot, or the client id'),
    caps: z.array(z.string()).describe('Capability strings of the device'),
    ts: z
      // the string first: it is what is sent, and a failed first try costs an issue per message
      .union([z.iso.datetime({ offset: true }), z.number()])
      .describe(
        "Time the message was made: an ISO 8601 string (the spec's form, what we send) or ms since the Unix epoch (accepted when reading)",
      ),
    payload: z.unknown().describe('The message body'),
  })
  .describe('HAL message envelope');
// Written out: Omit<> over the loose schema's index signature would erase the named fields.
export interface Envelope<P = unknown> {
  hal_major: number;
  hal_minor: number;
  schema: string;
  /** The sender: the robot on what a device publishes, the client's id on what a client sends. */
  device_id: string;
  caps: string[];
  /** An ISO 8601 string (the spec's form, what we send), or ms since the Unix epoch (read too). */
  ts: number | string;
  payload: P;
}

/** Wraps a payload in an envelope of this library's version, `ts` as the spec writes it (ISO 8601). */
export function makeEnvelope<P>(
  init: { schema: string; device_id: string; caps?: readonly string[]; ts?: number | string },
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
    ts: init.ts ?? isoNow(),
    payload,
  };
}

let isoMs = Number.NaN;
let isoText = '';

/**
 * Now as ISO 8601, to the millisecond. Formatting a date costs more than the rest of an envelope,
 * and a busy link makes many envelopes in one millisecond: they share one string.
 */
function isoNow(): string {
  const ms = Date.now();
  if (ms !== isoMs) {
    isoMs = ms;
    isoText = new Date(ms).toISOString();
  }
  return isoText;
}

/** When the envelope's `ts` says it was made, ms since the Unix epoch (either form of `ts`). */
export function envelopeTimeMs(envelope: Pick<Envelope, 'ts'>): number {
  return typeof envelope.ts === 'number' ? envelope.ts : Date.parse(envelope.ts);
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

/**
 * The parts of a subject. One addressing scheme (docs/nats.md): the spec's subjects
 * `hal.v{major}.{domain}.{type}.{action}` as written address the default device (the one a
 * spec-only client talks to); `hal.v{major}.dev.{device}.{domain}.{type}.{action}` addresses one
 * device of a fleet, so `hal.v1.dev.cube-01.>` is everything about one robot and
 * `hal.v1.dev.*.sensor.imu.data` one stream of every robot. `dev` is therefore not a domain.
 */
export interface SubjectParts {
  /** The addressed robot (`*` in a subscription: every robot); omitted: the default device. */
  device?: string | undefined;
  domain: string;
  type: string;
  action: string;
  major?: number;
}

/** The token after `hal.v{major}` that introduces a device id. */
export const DEVICE_SUBJECT_TOKEN = 'dev';

function subjectToken(name: string, value: string, allowWildcard: boolean): string {
  if (allowWildcard && (value === '*' || value === '>')) return value;
  const ok = name === 'device' ? DEVICE_ID.test(value) : TOKEN.test(value);
  if (!ok)
    throw new HalError('INVALID_PARAMETER', `subject "${name}" token is invalid: "${value}"`);
  if (name === 'domain' && value === DEVICE_SUBJECT_TOKEN) {
    throw new HalError('INVALID_PARAMETER', `subject "domain" may not be "${value}"`);
  }
  return value;
}

/**
 * Builds a subject: `hal.v1.motor.differential.cmd` for the default device, or
 * `hal.v1.dev.cube-01.motor.differential.cmd` with `device: 'cube-01'`.
 */
export function buildSubject(parts: SubjectParts, options: { wildcards?: boolean } = {}): string {
  const wild = options.wildcards ?? false;
  const major = parts.major ?? HAL_MAJOR;
  const tokens = [
    subjectToken('domain', parts.domain, wild),
    subjectToken('type', parts.type, wild),
    subjectToken('action', parts.action, wild),
  ];
  if (parts.device !== undefined) {
    tokens.unshift(DEVICE_SUBJECT_TOKEN, subjectToken('device', parts.device, wild));
  }
  const gt = tokens.indexOf('>');
  if (gt >= 0 && gt !== tokens.length - 1) {
    throw new HalError('INVALID_PARAMETER', 'subject wildcard ">" may only be last');
  }
  return `hal.v${major}.${tokens.join('.')}`;
}

/** Splits a concrete subject into its parts; throws INVALID_PARAMETER if it is not one of ours. */
export function parseSubject(subject: string): SubjectParts & { major: number } {
  const tokens = subject.split('.');
  const match = /^v(\d+)$/.exec(tokens[1] ?? '');
  const addressed = tokens.length === 7 && tokens[2] === DEVICE_SUBJECT_TOKEN;
  if (tokens[0] !== 'hal' || match === null || (tokens.length !== 5 && !addressed)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${subject}" is not a hal.v{major}[.dev.{device}].{domain}.{type}.{action} subject`,
    );
  }
  const [domain = '', type = '', action = ''] = tokens.slice(-3);
  const major = Number(match[1]);
  const parts: SubjectParts & { major: number } = addressed
    ? { device: tokens[3] ?? '', domain, type, action, major }
    : { domain, type, action, major };
  buildSubject(parts);
  return parts;
}
