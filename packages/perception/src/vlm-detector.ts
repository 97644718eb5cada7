import { AgentError, postChatCompletion } from '@hal/agent';
import type { ChatEndpoint } from '@hal/agent';
import { HalError, errorMessage } from '@hal/types';
import type { Detector, DetectorInput } from './detector.js';
import type { Detection } from './project-object.js';
import { vlmMessages, vlmRequestBody } from './vlm-prompt.js';
import type { VlmPromptOptions, VlmResponseFormat } from './vlm-prompt.js';
import { readEntries, replyEntries, replyText } from './vlm-reply.js';
import type { VlmReplyCounts } from './vlm-reply.js';
import { vlmFailure } from './vlm-errors.js';
import { visionModelSettings } from './vlm-options.js';
import type { VisionModelDetectorOptions } from './vlm-options.js';

export type { VisionModelDetectorOptions };

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
    const settings = visionModelSettings(options);
    this.#model = settings.model;
    this.name = `vlm:${settings.model}`;
    this.url = `${settings.baseUrl.replace(/\/+$/, '')}/chat/completions`;
    this.#timeoutMs = settings.timeoutMs;
    this.#vocabulary = {
      units: settings.boxUnits,
      colours: settings.colours,
      kinds: settings.kinds,
      maxObjects: settings.maxObjects,
    };
    this.#format = settings.responseFormat;
    this.#sampling = { temperature: settings.temperature, maxTokens: settings.maxTokens };
    this.#endpoint = {
      url: this.url,
      apiKey: settings.apiKey,
      requestTimeoutMs: settings.timeoutMs,
      retry: { maxRetries: settings.retries, baseDelayMs: 250, maxDelayMs: settings.timeoutMs },
      fetch: settings.fetch ?? globalThis.fetch,
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
              throw new AgentError('BAD_REPLY', errorMessage(error), {
                cause: error,
              });
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
