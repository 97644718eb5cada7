import { ErrorReplySchema } from '@hal/nats';
import { EnvelopeSchema, HAL_MAJOR, parseCapability } from '@hal/types';
import type { Envelope, HalErrorPayload } from '@hal/types';
import type { z } from 'zod';

/** A message from the device, checked against the envelope and a payload schema. */
export interface Inspected<T> {
  /** What is wrong with the envelope or the payload; empty when the message is valid. */
  issues: string[];
  envelope: Envelope | undefined;
  /** The payload, when it matched the expected schema. */
  payload: T | undefined;
  /** The error body, when the payload is the spec's error shape instead. */
  error: HalErrorPayload | undefined;
}

const decoder = new TextDecoder();

function firstIssue(error: z.ZodError): string {
  const issue = error.issues[0];
  if (issue === undefined) return 'invalid';
  return issue.path.length > 0 ? `${issue.path.join('.')}: ${issue.message}` : issue.message;
}

/**
 * Checks one message as a spec-only client reads it: JSON, the Tafy envelope, `ts` in ISO 8601
 * (the spec's form; a reader accepts ms too, a device must send the spec's), `hal_major`,
 * `device_id` (the sender: it must be the device under test), capability strings, and the
 * payload against `schema` (or the spec's error shape).
 */
export function inspect<S extends z.ZodType>(
  data: Uint8Array,
  schema: S,
  deviceId: string | undefined,
): Inspected<z.output<S>> {
  const result: Inspected<z.output<S>> = {
    issues: [],
    envelope: undefined,
    payload: undefined,
    error: undefined,
  };
  let raw: unknown;
  try {
    raw = JSON.parse(decoder.decode(data));
  } catch {
    result.issues.push('the message is not JSON');
    return result;
  }
  const envelope = EnvelopeSchema.safeParse(raw);
  if (!envelope.success) {
    result.issues.push(`not a HAL envelope (${firstIssue(envelope.error)})`);
    return result;
  }
  const env = envelope.data as Envelope;
  result.envelope = env;
  if (env.hal_major !== HAL_MAJOR) {
    result.issues.push(`hal_major is ${env.hal_major}, the spec's is ${HAL_MAJOR}`);
  }
  if (typeof env.ts !== 'string') {
    result.issues.push(
      `ts is ${JSON.stringify(env.ts)}, not an ISO 8601 string as the spec writes it ("2024-03-14T10:30:00.000Z")`,
    );
  }
  if (deviceId !== undefined && env.device_id !== deviceId) {
    result.issues.push(`device_id is "${env.device_id}", not the device "${deviceId}"`);
  }
  for (const cap of env.caps) {
    try {
      parseCapability(cap);
    } catch {
      result.issues.push(`caps holds "${cap}", not a {domain}.{type}:v{major}.{minor} string`);
    }
  }
  const failed = ErrorReplySchema.safeParse(env.payload);
  if (failed.success) {
    result.error = failed.data.error;
    return result;
  }
  const body = schema.safeParse(env.payload);
  if (body.success) result.payload = body.data;
  else result.issues.push(`payload of "${env.schema}": ${firstIssue(body.error)}`);
  return result;
}
