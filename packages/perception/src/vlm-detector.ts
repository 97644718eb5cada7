import { AgentError, postChatCompletion } from '@hal/agent';
import type { ChatEndpoint } from '@hal/agent';
import { HalError } from '@hal/types';
import type { Detector, DetectorInput } from './detector.js';
import { COLOUR_NAMES } from './palette.js';
import type { ColourName } from './palette.js';
import type { Detection } from './project-object.js';
import { VLM_KINDS } from './vlm-labels.js';
import type { VlmKind } from './vlm-labels.js';
import { vlmMessages, vlmRequestBody } from './vlm-prompt.js';
import type { VlmPromptOptions, VlmResponseFormat } from './vlm-prompt.js';
import { readEntries, replyEntries, replyText } from './vlm-reply.js';
import type { VlmBoxUnits, VlmReplyCounts } from './vlm-reply.js';
import { vlmFailure } from './vlm-errors.js';

/** Options of a {@link VisionModelDetector}. */
export interface VisionModelDetectorOptions {
  /** The OpenAI-compatible API's base URL, e.g. `http://localhost:11434/v1` (requests go to `{baseUrl}/chat/completions`). */
  baseUrl: string;
  /** The vision model, e.g. `gpt-4o-mini`, `qwen2.5vl:7b`. */
  model: string;
  /** The API key, sent as `Authorization: Bearer ...` when given. */
  apiKey?: string;
  /** Time allowed for one detection, all attempts included, ms. Default 20000. */
  timeoutMs?: number;
  /** Attempts after the first on HTTP 408/429/5xx, a network error or an unreadable reply. Default 1. */
  retries?: number;
  /** Most objects asked for and kept (the most confident). Default 10. */
  maxObjects?: number;
  /** The colours asked for and kept. Default all six of the palette's. */
  colours?: readonly ColourName[];
  /** The kinds asked for. Default box and pillar. */
  kinds?: readonly VlmKind[];
  /**
   * The box convention the prompt asks for: `pixels` of the frame (default) or `per-mille`
   * (0..1000 across the width and height, as Qwen2-VL and Gemini are trained to give). Only the
   * one asked for is read: a box in the other convention is not guessed at.
   */
  boxUnits?: VlmBoxUnits;
  /**
   * How the JSON reply is asked for: `json_schema` (default; structured output), `json_object`,
   * or `none` (only in the prompt). A server that refuses one with HTTP 400 is asked with the
   * next, and remembered.
   */
  responseFormat?: VlmResponseFormat;
  /** Sampling temperature. Default 0. */
  temperature?: number;
  /** Most tokens of the reply. Default 1000. */
  maxTokens?: number;
  /** The fetch used (a test seam). Default the global fetch. */
  fetch?: typeof fetch;
}

/** What the last detection received and kept. */
export interface VlmDetectionReport extends VlmReplyCounts {
  /** The response format the reply was asked for with. */
  responseFormat: VlmResponseFormat;
}

const FALLBACK: Readonly<Record<VlmResponseFormat, VlmResponseFormat | undefined>> = {
  json_schema: 'json_object',
  json_object: 'none',
  none: undefined,
};

function wholeNumber(name: string, value: number, least: number): number {
  if (!(Number.isInteger(value) && value >= least)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"${name}" must be a whole number of ${least} or more, got ${value}`,
      {
        details: { parameter: name, value },
      },
    );
  }
  return value;
}

/** A frame as a data URL: bare base64 is taken for a JPEG. */
function frameUrl(frame: string): string {
  return frame.startsWith('data:') ? frame : `data:image/jpeg;base64,${frame}`;
}

/**
 * A detector that asks any OpenAI-compatible vision model for labelled boxes: it sends the frame
 * with an instruction to answer JSON only (structured output where the server has it, else a
 * JSON block in its text is found), checks each object with a schema, drops and counts malformed
 * ones, cuts boxes to the image, and maps labels to the palette's colours and the kinds. Objects
 * of other colours cannot be represented and are dropped (counted in {@link last}). Perception
 * places each box on the floor by its bottom edge, through the camera model.
 *
 * A model that fails (unreachable, an HTTP error, no answer within `timeoutMs`, a reply with no
 * readable list of objects) rejects with a HalError naming the endpoint and the cause
 * (`NOT_CONNECTED`, `AUTH_FAILED`, `HARDWARE_ERROR` with `details.status`, `TIMEOUT`,
 * `MALFORMED`; `details.failure` says which), never with an empty list.
 */
export class VisionModelDetector implements Detector {
  readonly name: string;
  /** The URL requests go to. */
  readonly url: string;
  /** What the last successful detection received and kept; undefined before the first. */
  last: VlmDetectionReport | undefined;
  #format: VlmResponseFormat;
  readonly #model: string;
  readonly #timeoutMs: number;
  readonly #endpoint: ChatEndpoint;
  readonly #vocabulary: Pick<VlmPromptOptions, 'units' | 'colours' | 'kinds' | 'maxObjects'>;
  readonly #sampling: { temperature: number; maxTokens: number };

  constructor(options: VisionModelDetectorOptions) {
    if (typeof options.model !== 'string' || options.model.trim() === '') {
      throw new HalError('INVALID_PARAMETER', '"model" must name the vision model', {
        details: { parameter: 'model' },
      });
    }
    let base: URL;
    try {
      base = new URL(options.baseUrl);
    } catch (cause) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"baseUrl" must be a URL, got ${JSON.stringify(options.baseUrl)}`,
        {
          details: { parameter: 'baseUrl', value: options.baseUrl },
          cause,
        },
      );
    }
    this.#model = options.model;
    this.name = `vlm:${options.model}`;
    this.url = `${base.href.replace(/\/+$/, '')}/chat/completions`;
    this.#timeoutMs = wholeNumber('timeoutMs', options.timeoutMs ?? 20_000, 1);
    const colours = options.colours ?? COLOUR_NAMES;
    const kinds = options.kinds ?? VLM_KINDS;
    for (const colour of colours) {
      if (!(COLOUR_NAMES as readonly string[]).includes(colour)) {
        throw new HalError(
          'INVALID_PARAMETER',
          `"colours" must be among ${COLOUR_NAMES.join(', ')}, got ${JSON.stringify(colour)}`,
          {
            details: { parameter: 'colours', value: colour },
          },
        );
      }
    }
    if (colours.length === 0) {
      throw new HalError('INVALID_PARAMETER', '"colours" must name at least one colour', {
        details: { parameter: 'colours' },
      });
    }
    for (const kind of kinds) {
      if (!(VLM_KINDS as readonly string[]).includes(kind)) {
        throw new HalError(
          'INVALID_PARAMETER',
          `"kinds" must be among ${VLM_KINDS.join(', ')}, got ${JSON.stringify(kind)}`,
          {
            details: { parameter: 'kinds', value: kind },
          },
        );
      }
    }
    this.#vocabulary = {
      units: options.boxUnits ?? 'pixels',
      colours: [...colours],
      kinds: [...kinds],
      maxObjects: wholeNumber('maxObjects', options.maxObjects ?? 10, 1),
    };
    this.#format = options.responseFormat ?? 'json_schema';
    this.#sampling = {
      temperature: options.temperature ?? 0,
      maxTokens: wholeNumber('maxTokens', options.maxTokens ?? 1000, 1),
    };
    this.#endpoint = {
      url: this.url,
      apiKey: options.apiKey,
      requestTimeoutMs: this.#timeoutMs,
      retry: {
        maxRetries: wholeNumber('retries', options.retries ?? 1, 0),
        baseDelayMs: 250,
        maxDelayMs: this.#timeoutMs,
      },
      fetch: options.fetch ?? globalThis.fetch,
    };
  }

  /** The response format asked for now (it drops to the next when a server refuses one). */
  get responseFormat(): VlmResponseFormat {
    return this.#format;
  }

  /**
   * Asks the model for the objects in `input.frame` (which must be the frame's JPEG, as
   * `FramePerceiver.perceive` passes it). Rejects with a HalError when the model fails.
   */
  async detect(input: DetectorInput): Promise<Detection[]> {
    if (input.frame === '') {
      throw new HalError(
        'INVALID_PARAMETER',
        `${this.name} needs the frame's JPEG (a data URL or base64), and was given only the decoded image`,
        { details: { detector: this.name } },
      );
    }
    const { width, height } = input.image;
    const prompt: VlmPromptOptions = { width, height, ...this.#vocabulary };
    const messages = vlmMessages(frameUrl(input.frame), prompt);
    const deadline = AbortSignal.timeout(this.#timeoutMs);
    for (;;) {
      const format = this.#format;
      const body = vlmRequestBody({ model: this.#model, ...this.#sampling }, messages, format);
      try {
        const entries = await postChatCompletion(
          this.#endpoint,
          body,
          (reply) => {
            try {
              return replyEntries(replyText(reply));
            } catch (error) {
              // Unreadable: postChatCompletion asks again while it may.
              throw new AgentError(
                'BAD_REPLY',
                error instanceof Error ? error.message : String(error),
                {
                  cause: error,
                },
              );
            }
          },
          deadline,
          () => undefined,
        );
        const { detections, counts } = readEntries(entries, {
          ...prompt,
          detector: this.name,
        });
        this.last = { ...counts, responseFormat: format };
        return detections;
      } catch (error) {
        const next = FALLBACK[format];
        const status = error instanceof AgentError ? error.details?.['status'] : undefined;
        if (status === 400 && next !== undefined && !deadline.aborted) {
          // The server does not take this response format: ask with the next from now on.
          this.#format = next;
          continue;
        }
        throw vlmFailure(error, {
          detector: this.name,
          url: this.url,
          timeoutMs: this.#timeoutMs,
          timedOut: deadline.aborted,
        });
      }
    }
  }
}
