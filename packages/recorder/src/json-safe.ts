/** Longest string kept whole in a call record; longer ones (frames) are shortened. */
export const MAX_RECORDED_STRING = 512;

/** Nesting past which a value is copied, not checked (a cycle is caught by the copy). */
const MAX_CHECKED_DEPTH = 32;

/**
 * A JSON-safe form of a call's arguments or result: long strings shortened (a camera frame goes
 * to its own topic), non-finite numbers and bigints as strings, functions and cycles left out.
 * A value that is already JSON-safe (plain objects, arrays, finite numbers, short strings, as
 * almost every call's are) is handed back as it is, not copied: `JSON.stringify` makes the same
 * text of it as of a copy.
 */
export function jsonSafe(value: unknown): unknown {
  return isPlainJson(value, 0) ? value : jsonSafeCopy(value);
}

/** Whether `JSON.stringify(value)` is the text of {@link jsonSafeCopy}'s copy, with nothing to copy. */
function isPlainJson(value: unknown, depth: number): boolean {
  switch (typeof value) {
    case 'string':
      return value.length <= MAX_RECORDED_STRING;
    case 'number':
      return Number.isFinite(value);
    case 'boolean':
      return true;
    case 'undefined':
      // left out of an object, null in an array, by both; a value that is undefined is not plain
      return depth > 0;
    case 'object':
      break;
    default:
      return false;
  }
  if (value === null) return true;
  if (depth >= MAX_CHECKED_DEPTH) return false;
  if (Array.isArray(value)) {
    for (const item of value as unknown[]) if (!isPlainJson(item, depth + 1)) return false;
    return true;
  }
  // an Error, a Date (its toJSON), a Map or a class instance: the copy decides
  const proto: unknown = Object.getPrototypeOf(value);
  if (proto !== Object.prototype && proto !== null) return false;
  const record = value as Record<string, unknown>;
  for (const key in record) {
    if (!isPlainJson(record[key], depth + 1)) return false;
  }
  return true;
}

/** The copy {@link jsonSafe} makes of a value that is not already JSON-safe. */
export function jsonSafeCopy(value: unknown, seen = new WeakSet<object>()): unknown {
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
    if (Array.isArray(value)) return value.map((item) => jsonSafeCopy(item, seen) ?? null);
    if (value instanceof Error) return { name: value.name, message: value.message };
    const out: Record<string, unknown> = {};
    for (const [key, item] of Object.entries(value)) {
      const safe = jsonSafeCopy(item, seen);
      if (safe !== undefined) out[key] = safe;
    }
    return out;
  } finally {
    // only the path from the root counts: a value met twice side by side is not a cycle
    seen.delete(value);
  }
}
