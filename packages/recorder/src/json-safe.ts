/** Longest string kept whole in a call record; longer ones (frames) are shortened. */
export const MAX_RECORDED_STRING = 512;

/**
 * A JSON-safe copy of a call's arguments or result: long strings shortened (a camera frame goes
 * to its own topic), non-finite numbers and bigints as strings, functions and cycles left out.
 */
export function jsonSafe(value: unknown, seen = new WeakSet<object>()): unknown {
  if (typeof value === 'string') {
    return value.length > MAX_RECORDED_STRING
      ? `${value.slice(0, 64)}... (${value.length} characters)`
      : value;
  }
  if (typeof value === 'number') return Number.isFinite(value) ? value : String(value);
  if (typeof value === 'bigint') return value.toString();
  if (typeof value === 'boolean' || value === null) return value;
  if (value === undefined || typeof value === 'function' || typeof value === 'symbol') {
    return undefined;
  }
  if (seen.has(value)) return '[circular]';
  seen.add(value);
  try {
    if (Array.isArray(value)) return value.map((item) => jsonSafe(item, seen) ?? null);
    if (value instanceof Error) return { name: value.name, message: value.message };
    const out: Record<string, unknown> = {};
    for (const [key, item] of Object.entries(value)) {
      const safe = jsonSafe(item, seen);
      if (safe !== undefined) out[key] = safe;
    }
    return out;
  } finally {
    // only the path from the root counts: a value met twice side by side is not a cycle
    seen.delete(value);
  }
}
