/**
 * The reason text of an emergency stop. An e-stop is never refused because of its argument: any
 * value is turned into a short, printable reason by {@link sanitizeEstopReason}, the one rule
 * every HAL, the mock robot and the firmware follow, so the reason reported is the one stored.
 */

/**
 * The most UTF-8 bytes of a stored reason: what the firmware's reason buffer keeps (64 bytes with
 * its terminator). With no control characters left, JSON escaping at most doubles it (`"` and
 * `\`), so an `estop` message stays far below the protocol's 1024-byte limit.
 */
export const ESTOP_REASON_MAX_BYTES = 63;

/** The reason stored when none is given (or nothing printable is left of it). */
export const DEFAULT_ESTOP_REASON = 'emergency stop';

// C0 controls, DEL and C1 controls; lone surrogates are handled by toWellFormed below.
// eslint-disable-next-line no-control-regex
const CONTROL = /[\u0000-\u001f\u007f-\u009f]+/g;

const encoder = new TextEncoder();

/** Only this many UTF-16 code units of a reason are read. */
const ESTOP_REASON_READ_UNITS = 4096;

/** Replaces each lone UTF-16 surrogate with U+FFFD (String#toWellFormed, Node 20+). */
function wellFormed(text: string): string {
  let out = '';
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (c >= 0xd800 && c <= 0xdbff) {
      const next = text.charCodeAt(i + 1);
      if (next >= 0xdc00 && next <= 0xdfff) {
        out += text[i]! + text[i + 1]!;
        i += 1;
        continue;
      }
      out += '\ufffd';
    } else if (c >= 0xdc00 && c <= 0xdfff) {
      out += '\ufffd';
    } else {
      out += text[i]!;
    }
  }
  return out;
}

function asText(value: unknown): string | undefined {
  switch (typeof value) {
    case 'string':
      return value;
    case 'number':
    case 'bigint':
    case 'boolean':
      return String(value);
    case 'undefined':
      return undefined;
    default:
      if (value === null) return undefined;
      if (value instanceof Error) return value.message;
      // objects, arrays, symbols, functions: no text of their own worth storing
      return undefined;
  }
}

/**
 * Turns any value into the reason an e-stop stores, never throwing:
 * - a string is kept (its first 4096 UTF-16 code units); a number, bigint or boolean becomes its text; an Error its message;
 *   anything else (undefined, null, objects, symbols, functions) gives {@link DEFAULT_ESTOP_REASON};
 * - lone UTF-16 surrogates become U+FFFD;
 * - every run of control characters (U+0000..U+001F, U+007F..U+009F) becomes one space, and the
 *   ends are trimmed; an empty result gives the default;
 * - the text is cut to at most {@link ESTOP_REASON_MAX_BYTES} UTF-8 bytes, never inside a
 *   character, and trimmed again.
 */
export function sanitizeEstopReason(value: unknown): string {
  const raw = asText(value);
  if (raw === undefined) return DEFAULT_ESTOP_REASON;
  // only a bounded prefix is read: a megabyte of text must not cost a megabyte of scanning
  const text = wellFormed(raw.slice(0, ESTOP_REASON_READ_UNITS)).replace(CONTROL, ' ').trim();
  if (text === '') return DEFAULT_ESTOP_REASON;
  if (encoder.encode(text).length <= ESTOP_REASON_MAX_BYTES) return text;
  let bytes = 0;
  let cut = '';
  for (const char of text) {
    const size = encoder.encode(char).length;
    if (bytes + size > ESTOP_REASON_MAX_BYTES) break;
    bytes += size;
    cut += char;
  }
  const trimmed = cut.trim();
  return trimmed === '' ? DEFAULT_ESTOP_REASON : trimmed;
}
