import { HAL_MAJOR, HAL_MINOR, HalError, makeEnvelope, parseEnvelope } from '@hal/types';
import type { Envelope } from '@hal/types';
import type { z } from 'zod';

const encoder = new TextEncoder();
const decoder = new TextDecoder();

/** Encodes a payload in an envelope sent by `deviceId`. */
export function encodeMessage(
  schema: string,
  deviceId: string,
  caps: readonly string[],
  payload: unknown,
): Uint8Array {
  return encoder.encode(
    JSON.stringify(makeEnvelope({ schema, device_id: deviceId, caps }, payload)),
  );
}

/** The message's bytes as JSON; MALFORMED when they are not. */
function readJson(data: Uint8Array): unknown {
  try {
    return JSON.parse(decoder.decode(data));
  } catch (cause) {
    throw new HalError('MALFORMED', 'message is not JSON', { cause });
  }
}

/** Decodes an envelope and checks its payload; MALFORMED for anything else. */
export function decodeMessage<S extends z.ZodType>(
  data: Uint8Array,
  payload: S,
): Envelope<z.output<S>> {
  const raw = readJson(data);
  return parseEnvelope(raw, payload);
}

/** The sender of a bare spec payload, which names nobody (never a valid device id). */
export const UNNAMED_SENDER = '(unnamed)';

/**
 * Decodes a message on one of the spec's subjects: an envelope, or a bare spec payload (the spec's
 * own example driver reads a command's fields at the top level), which is taken as HAL v1 from
 * {@link UNNAMED_SENDER}. A JSON object with any envelope field is held to the envelope; what is
 * neither a valid envelope nor a valid bare payload is MALFORMED.
 */
export function decodeSpecMessage<S extends z.ZodType>(
  data: Uint8Array,
  payload: S,
): Envelope<z.output<S>> {
  const raw = readJson(data);
  if (typeof raw !== 'object' || raw === null || Array.isArray(raw) || looksLikeEnvelope(raw)) {
    return parseEnvelope(raw, payload);
  }
  const body = payload.safeParse(raw);
  if (!body.success) {
    throw new HalError(
      'MALFORMED',
      `neither a HAL envelope nor a bare payload: ${body.error.issues[0]?.message ?? 'invalid'}`,
    );
  }
  return {
    hal_major: HAL_MAJOR,
    hal_minor: HAL_MINOR,
    schema: 'bare',
    device_id: UNNAMED_SENDER,
    caps: [],
    ts: new Date().toISOString(),
    payload: body.data,
  };
}

const ENVELOPE_FIELDS = ['hal_major', 'hal_minor', 'schema', 'device_id', 'caps', 'ts', 'payload'];

function looksLikeEnvelope(raw: object): boolean {
  return ENVELOPE_FIELDS.some((field) => field in raw);
}

// JSON has no NaN, Infinity or undefined; call arguments keep them, so a NaN power is refused
// for being NaN (INVALID_PARAMETER), exactly as a local call would be.
const TAG = '$hal';

/** Call arguments as JSON values, keeping NaN, +-Infinity and undefined. */
export function encodeArgs(args: readonly unknown[]): unknown[] {
  const out = args.map((arg) => {
    if (arg === undefined) return { [TAG]: 'undefined' };
    if (typeof arg === 'number' && !Number.isFinite(arg)) return { [TAG]: String(arg) };
    return arg;
  });
  while (out.length > 0 && isTagged(out[out.length - 1], 'undefined')) out.pop();
  return out;
}

function isTagged(value: unknown, tag: string): boolean {
  return (
    typeof value === 'object' && value !== null && (value as Record<string, unknown>)[TAG] === tag
  );
}

/** The inverse of {@link encodeArgs}. */
export function decodeArgs(args: readonly unknown[]): unknown[] {
  return args.map((arg) => {
    if (typeof arg !== 'object' || arg === null) return arg;
    const tag = (arg as Record<string, unknown>)[TAG];
    if (tag === 'undefined') return undefined;
    if (tag === 'NaN' || tag === 'Infinity' || tag === '-Infinity') return Number(tag);
    return arg;
  });
}
