import { errorMessage } from '@hal/types';
/** Parsed tool arguments, or why they could not be parsed. */
export type ParsedArguments =
  { ok: true; args: Record<string, unknown> } | { ok: false; message: string };

/**
 * Tool arguments as an object: JSON text (as chat-completions sends them), an object, or nothing
 * (no arguments). Anything else is refused with a message the LLM can act on.
 */
export function parseArguments(raw: string | Record<string, unknown> | undefined): ParsedArguments {
  let value: unknown = raw;
  if (raw === undefined || (typeof raw === 'string' && raw.trim() === ''))
    return { ok: true, args: {} };
  if (typeof raw === 'string') {
    try {
      value = JSON.parse(raw);
    } catch (error) {
      const why = errorMessage(error);
      return { ok: false, message: `arguments are not valid JSON (${why}); send a JSON object` };
    }
  }
  if (value === null || typeof value !== 'object' || Array.isArray(value)) {
    return {
      ok: false,
      message: `arguments must be a JSON object, got ${Array.isArray(value) ? 'an array' : typeof value}`,
    };
  }
  return { ok: true, args: value as Record<string, unknown> };
}
