import { errorMessage } from '../errors.js';
import { AttemptError } from './llm-attempt-error.js';
import type { LlmSettings, ResponseFormatMode } from './llm-options.js';
import { requestBody } from './llm-prompt.js';
import type { ChatMessage } from './llm-prompt.js';
import { replyContent } from './llm-reply.js';

/**
 * One chat-completions endpoint: a POST per request, bounded by `timeoutMs`, answering the
 * reply's text. Failures are AttemptErrors that say whether to ask again: a timeout, a network
 * error, HTTP 408, 429 or 5xx, or a reply without content may pass; other HTTP errors will not.
 * A server that refuses `json_schema` with HTTP 400 is asked for `json_object` from then on.
 */
export class ChatCompletionsClient {
  /** The response format asked for now (it drops to `json_object` when `json_schema` is refused). */
  format: ResponseFormatMode;
  readonly #settings: LlmSettings;

  constructor(settings: LlmSettings) {
    this.#settings = settings;
    this.format = settings.responseFormat;
  }

  /** Sends `messages` and answers the reply's text; rejects with what `signal` aborts with. */
  async complete(
    messages: ChatMessage[],
    schema: Record<string, unknown>,
    signal: AbortSignal,
  ): Promise<string> {
    const { apiKey, model, temperature, maxTokens, timeoutMs, logger } = this.#settings;
    const body = requestBody(
      { model, temperature, maxTokens, format: this.format },
      messages,
      schema,
    );
    const headers: Record<string, string> = { 'content-type': 'application/json' };
    if (apiKey !== undefined && apiKey !== '') headers['authorization'] = `Bearer ${apiKey}`;
    const timeout = AbortSignal.timeout(timeoutMs);
    let response: Response;
    let text: string;
    try {
      response = await this.#settings.fetch(this.#settings.url, {
        method: 'POST',
        headers,
        body: JSON.stringify(body),
        signal: AbortSignal.any([signal, timeout]),
      });
      text = await response.text();
    } catch (error) {
      if (signal.aborted) throw error;
      if (timeout.aborted) throw new AttemptError(`no reply within ${timeoutMs} ms`, true);
      throw new AttemptError(`request failed: ${errorMessage(error)}`, true);
    }
    if (!response.ok) {
      const snippet = text.slice(0, 200);
      if (response.status === 400 && this.format === 'json_schema') {
        // Many servers do not support structured output: ask for plain JSON instead.
        this.format = 'json_object';
        logger.warn('server refused json_schema; using json_object', { status: response.status });
        throw new AttemptError(`HTTP 400 with json_schema (${snippet})`, true);
      }
      const retryable =
        response.status === 408 || response.status === 429 || response.status >= 500;
      throw new AttemptError(`HTTP ${response.status}: ${snippet}`, retryable);
    }
    let payload: unknown;
    try {
      payload = JSON.parse(text);
    } catch {
      throw new AttemptError('the server answered with something that is not JSON', true);
    }
    return replyContent(payload);
  }
}
