import { AgentError, postChatCompletion, retryableStatus } from '@hal/agent';
import type { ChatEndpoint } from '@hal/agent';
import type { RetryPolicy } from '@hal/types';
import { AttemptError } from './llm-attempt-error.js';
import type { LlmSettings, ResponseFormatMode } from './llm-options.js';
import { requestBody } from './llm-prompt.js';
import type { ChatMessage } from './llm-prompt.js';
import { replyContent } from './llm-reply.js';

/** The longest wait a server may ask for (Retry-After) before the provider gives up on it, ms. */
export const MAX_RETRY_AFTER_MS = 30_000;

/**
 * How the provider asks again: the one retry policy of `@hal/types` (the agent's too), with the
 * provider's own attempts and a first wait of 125-250 ms. The provider runs the attempts itself,
 * so a reply that breaks the schema counts among them; the endpoint makes one request per call.
 */
export function decisionRetry(maxAttempts: number): RetryPolicy {
  return { maxRetries: maxAttempts - 1, baseDelayMs: 250, maxDelayMs: MAX_RETRY_AFTER_MS };
}

/**
 * One chat-completions endpoint, reached through `@hal/agent`'s OpenAI-compatible client with one
 * request per call (the provider counts the attempts, a reply that breaks the schema among them).
 * Failures are AttemptErrors that say whether to ask again, and after how long when the server
 * said (Retry-After): a timeout, a network error, HTTP 408, 429 or 5xx, or a reply without
 * content may pass; other HTTP errors will not. A server that refuses `json_schema` with HTTP 400
 * is asked for `json_object` from then on.
 */
export class ChatCompletionsClient {
  /** The response format asked for now (it drops to `json_object` when `json_schema` is refused). */
  format: ResponseFormatMode;
  readonly #settings: LlmSettings;
  readonly #endpoint: ChatEndpoint;

  constructor(settings: LlmSettings) {
    this.#settings = settings;
    this.format = settings.responseFormat;
    this.#endpoint = {
      url: settings.url,
      apiKey: settings.apiKey,
      requestTimeoutMs: settings.timeoutMs,
      retry: { ...decisionRetry(settings.maxAttempts), maxRetries: 0 },
      fetch: settings.fetch,
    };
  }

  /** Sends `messages` and answers the reply's text; rejects with what `signal` aborts with. */
  async complete(
    messages: ChatMessage[],
    schema: Record<string, unknown>,
    signal: AbortSignal,
  ): Promise<string> {
    const { model, temperature, maxTokens, logger } = this.#settings;
    const body = requestBody(
      { model, temperature, maxTokens, format: this.format },
      messages,
      schema,
    );
    let payload: unknown;
    try {
      payload = await postChatCompletion(
        this.#endpoint,
        body,
        (reply) => reply,
        signal,
        () => undefined,
      );
    } catch (error) {
      if (signal.aborted || !(error instanceof AgentError)) throw error;
      const status = error.details?.['status'];
      if (error.code !== 'HTTP' || typeof status !== 'number') {
        throw new AttemptError(error.message, true);
      }
      if (status === 400 && this.format === 'json_schema') {
        // Many servers do not support structured output: ask for plain JSON instead.
        this.format = 'json_object';
        logger.warn('server refused json_schema; using json_object', { status });
        throw new AttemptError(`json_schema refused: ${error.message}`, true);
      }
      const waitMs = error.details?.['retryAfterMs'];
      throw new AttemptError(
        error.message,
        retryableStatus(status),
        undefined,
        typeof waitMs === 'number' ? waitMs : undefined,
      );
    }
    return replyContent(payload);
  }
}
