import { isHalError, errorMessage } from '@hal/types';
import type { HALToolResult } from '@hal/types';

/** One piece of a tool result: text, or an image where the format has images. */
export type ToolContent =
  | { type: 'text'; text: string }
  | { type: 'image'; data: string /* base64 */; mimeType: 'image/jpeg' };

/** What a tool call answers; an LLM reads `content`, an app may read `structured`. */
export interface ToolResult {
  isError: boolean;
  /** Text (JSON of the result) and, for frames, an image. */
  content: ToolContent[];
  /** The HALToolResult, or the value a read call answered. */
  structured?: Record<string, unknown>;
  /** The HalErrorCode, or the executor's own (UNKNOWN_TOOL, BAD_ARGUMENTS, TIMEOUT, DENIED, LEASH_...). */
  code?: string;
}

/** A refusal or failure the LLM can read and recover from. */
export function errorResult(code: string, message: string): ToolResult {
  return {
    isError: true,
    code,
    content: [{ type: 'text', text: JSON.stringify({ error: message, code }) }],
    structured: { error: message, code },
  };
}

/** The result of a call that answers a HALToolResult. */
export function fromHalResult(result: HALToolResult): ToolResult {
  const structured = result as unknown as Record<string, unknown>;
  return {
    isError: !result.success,
    ...(result.code === undefined ? {} : { code: result.code }),
    content: [{ type: 'text', text: JSON.stringify(result) }],
    structured,
  };
}

const DATA_URL = /^data:image\/jpeg;base64,(.*)$/s;

/** The result of a read call: its value as JSON, a frame as an image. */
export function fromValue(value: unknown): ToolResult {
  if (typeof value === 'string') {
    const frame = DATA_URL.exec(value);
    if (frame !== null) {
      const data = frame[1] ?? '';
      const bytes = Math.floor((data.length * 3) / 4);
      return {
        isError: false,
        content: [
          { type: 'text', text: JSON.stringify({ frame: 'image/jpeg', bytes }) },
          { type: 'image', data, mimeType: 'image/jpeg' },
        ],
        structured: { frame: 'image/jpeg', bytes },
      };
    }
  }
  const structured =
    typeof value === 'object' && value !== null && !Array.isArray(value)
      ? (value as Record<string, unknown>)
      : { value };
  return { isError: false, content: [{ type: 'text', text: JSON.stringify(value) }], structured };
}

/** A read call's rejection (always a HalError from a HAL) as a result. */
export function fromThrown(thrown: unknown): ToolResult {
  if (isHalError(thrown)) return errorResult(thrown.code, thrown.message);
  return errorResult('HARDWARE_ERROR', errorMessage(thrown));
}
