import { HalError } from '@hal/types';
import { z } from 'zod';
import { COLOUR_NAMES } from './palette.js';
import { VLM_KINDS } from './vlm-labels.js';

/** The options of a `VisionModelDetector`, checked, with their defaults. */
export const VisionModelDetectorOptionsSchema = z.object({
  /**
   * The OpenAI-compatible API's base URL, e.g. `http://127.0.0.1:11434/v1`; requests go to
   * `{baseUrl}/chat/completions`.
   */
  baseUrl: z
    .string()
    .refine(
      (url) => URL.canParse(url) && /^https?:$/.test(new URL(url).protocol),
      'must be an http(s) URL',
    ),
  /** The vision model, e.g. `gpt-4o-mini`, `qwen2.5vl:7b`. */
  model: z.string().trim().min(1, 'must name the vision model'),
  /** The API key, sent as `Authorization: Bearer ...` when given. */
  apiKey: z.string().optional(),
  /** Time allowed for one detection, all attempts included, ms. Default 20000. */
  timeoutMs: z.number().int().min(1).default(20_000),
  /** Attempts after the first on HTTP 408/429/5xx, a network error or an unreadable reply. Default 1. */
  retries: z.number().int().min(0).default(1),
  /** Most objects asked for and kept (the most confident). Default 10. */
  maxObjects: z.number().int().min(1).default(10),
  /** The colours asked for and kept. Default all six of the palette's. */
  colours: z
    .array(z.enum(COLOUR_NAMES))
    .min(1)
    .default([...COLOUR_NAMES]),
  /** The kinds asked for (another kind word reads as `unknown`). Default box and pillar. */
  kinds: z.array(z.enum(VLM_KINDS)).default([...VLM_KINDS]),
  /**
   * The box convention the prompt asks for: `pixels` of the frame (default) or `per-mille`
   * (0..1000 across the width and height, as Qwen2-VL and Gemini are trained to give). Only the
   * one asked for is read: a box in the other convention is not guessed at.
   */
  boxUnits: z.enum(['pixels', 'per-mille']).default('pixels'),
  /**
   * How the JSON reply is asked for: `json_schema` (default; structured output), `json_object`,
   * or `none` (only in the prompt). A server that refuses one with HTTP 400 is asked with the
   * next, and remembered.
   */
  responseFormat: z.enum(['json_schema', 'json_object', 'none']).default('json_schema'),
  /** Sampling temperature. Default 0. */
  temperature: z.number().min(0).max(2).default(0),
  /** Most tokens of the reply. Default 1000. */
  maxTokens: z.number().int().min(1).default(1000),
  /** The fetch used (a test seam). Default the global fetch. */
  fetch: z
    .custom<typeof fetch>((value) => typeof value === 'function', 'must be a function')
    .optional(),
});

/** Options of a `VisionModelDetector` (see {@link VisionModelDetectorOptionsSchema}). */
export type VisionModelDetectorOptions = z.input<typeof VisionModelDetectorOptionsSchema>;
/** The options with their defaults filled in. */
export type VisionModelDetectorSettings = z.output<typeof VisionModelDetectorOptionsSchema>;

const lowerFirst = (text: string) => text.charAt(0).toLowerCase() + text.slice(1);

/** Checks `options`: a HalError `INVALID_PARAMETER` that quotes the first wrong one. */
export function visionModelSettings(
  options: VisionModelDetectorOptions,
): VisionModelDetectorSettings {
  const parsed = VisionModelDetectorOptionsSchema.safeParse(options);
  if (parsed.success) return parsed.data;
  const issue = parsed.error.issues[0];
  const parameter = String(issue?.path[0] ?? 'options');
  const value: unknown = (options as Record<string, unknown> | undefined)?.[parameter];
  const shown = typeof value === 'function' ? 'a function' : JSON.stringify(value);
  throw new HalError(
    'INVALID_PARAMETER',
    `"${parameter}": ${lowerFirst(issue?.message ?? 'invalid')}, got ${shown ?? 'nothing'}`,
    { details: { parameter, value }, cause: parsed.error },
  );
}
