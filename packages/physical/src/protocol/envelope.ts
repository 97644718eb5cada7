import { ReplyEnvelopeSchema } from './schemas.js';
import type { ReplyEnvelope } from './schemas.js';

/*
 * The reply envelope, checked by hand on the hot path. Every reply goes through it, and the zod
 * schema copies the message and allocates as it checks; a successful reply (no `error`) is checked
 * here in place instead. This path only ever accepts: anything it is not sure of (an `error`
 * object, a `null` to turn into absent, a non-plain value) goes to ReplyEnvelopeSchema, which
 * stays the definition. The property test in envelope.property.test.ts holds the two equal:
 * whatever this path accepts, the schema accepts with the same output.
 */

const UINT32_MAX = 4_294_967_295;

const isUint32 = (value: unknown): boolean =>
  typeof value === 'number' && Number.isInteger(value) && value >= 0 && value <= UINT32_MAX;

/**
 * The envelope of `value` when the fast path is sure of it (`value` itself, unchanged), else
 * undefined: then the schema decides.
 */
export function fastEnvelope(
  value: unknown,
): (ReplyEnvelope & Record<string, unknown>) | undefined {
  if (typeof value !== 'object' || value === null || Array.isArray(value)) return undefined;
  if (Object.getPrototypeOf(value) !== Object.prototype) return undefined;
  const v = value as Record<string, unknown>;
  if (typeof v['ok'] !== 'boolean') return undefined;
  if (v['seq'] !== undefined && !isUint32(v['seq'])) return undefined;
  if (v['sid'] !== undefined && !isUint32(v['sid'])) return undefined;
  if (v['cmd'] !== undefined && typeof v['cmd'] !== 'string') return undefined;
  if (v['error'] !== undefined) return undefined;
  // a key present with the value undefined cannot come from JSON; the schema keeps such keys
  // exactly as this path does, but `__proto__` it would copy differently
  if (Object.hasOwn(v, '__proto__')) return undefined;
  return v as ReplyEnvelope & Record<string, unknown>;
}

/** The envelope of a parsed reply: the fast path, else the schema's verdict. */
export function parseEnvelope(
  value: unknown,
):
  | { success: true; data: ReplyEnvelope & Record<string, unknown> }
  | ReturnType<typeof ReplyEnvelopeSchema.safeParse> {
  const fast = fastEnvelope(value);
  if (fast !== undefined) return { success: true, data: fast };
  return ReplyEnvelopeSchema.safeParse(value);
}
