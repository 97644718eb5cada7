import { backoffMs, delay, errorMessage } from '@hal/types';
import type { ScopedLogger } from '@hal/types';
import { NavigationError } from '../errors.js';
import { AttemptError } from './llm-attempt-error.js';
import { ChatCompletionsClient, decisionRetry } from './llm-http.js';
import { resolveLlmSettings } from './llm-options.js';
import type { LlmSettings, OpenAICompatibleOptions } from './llm-options.js';
import { decisionBounds, SYSTEM_PROMPT, userContent } from './llm-prompt.js';
import type { ChatMessage, ContentPart } from './llm-prompt.js';
import { parseReply } from './llm-reply.js';
import type { DecisionContext, DecisionProvider } from './provider.js';
import { decisionJsonSchema } from './schema.js';
import type { NavigationDecision } from './schema.js';

/**
 * A decision provider backed by any OpenAI-compatible chat-completions endpoint (OpenAI, vLLM,
 * Ollama, llama.cpp server, LM Studio, ...). Each decision sends the camera frame as an image,
 * the world summary, the goal and the previous result, asks for the decision's JSON Schema as
 * structured output, and validates the reply with zod. A reply that is not JSON or breaks the
 * schema is answered with the problem and asked again; a timeout, HTTP 429 or 5xx is retried,
 * after the wait the server asks for (Retry-After, up to 30 s; a longer one ends the attempts);
 * when no attempt gives a valid decision the fallback provider decides (or the call rejects with
 * a NavigationError PROVIDER_ERROR).
 */
export class OpenAICompatibleProvider implements DecisionProvider {
  readonly name: string;
  readonly wantsFrame: boolean;
  readonly #settings: LlmSettings;
  readonly #client: ChatCompletionsClient;
  readonly #system: string;
  readonly #logger: ScopedLogger;

  constructor(options: OpenAICompatibleOptions = {}) {
    this.#settings = resolveLlmSettings(options);
    this.#client = new ChatCompletionsClient(this.#settings);
    this.#system = this.#settings.systemPrompt ?? SYSTEM_PROMPT;
    this.#logger = this.#settings.logger;
    this.wantsFrame = this.#settings.sendFrame;
    this.name = `llm:${this.#settings.model}`;
  }

  async decide(context: DecisionContext, signal: AbortSignal): Promise<NavigationDecision> {
    const { maxAttempts } = this.#settings;
    const retry = decisionRetry(maxAttempts);
    const bounds = decisionBounds(context.grid.spec);
    const schema = decisionJsonSchema(bounds);
    const messages: ChatMessage[] = [
      { role: 'system', content: this.#system },
      { role: 'user', content: this.#userContent(context, schema) },
    ];
    const problems: string[] = [];
    let builtFor = this.#client.format;
    for (let attempt = 1; attempt <= maxAttempts; attempt += 1) {
      if (signal.aborted) throw this.#aborted(signal);
      if (builtFor !== this.#client.format) {
        // The server refused structured output: the schema now goes in the prompt.
        messages[1] = { role: 'user', content: this.#userContent(context, schema) };
        builtFor = this.#client.format;
      }
      let reply: string | undefined;
      try {
        reply = await this.#client.complete(messages, schema, signal);
        return parseReply(reply, bounds);
      } catch (error) {
        if (signal.aborted) throw this.#aborted(signal);
        const failure =
          error instanceof AttemptError ? error : new AttemptError(errorMessage(error), false);
        problems.push(`attempt ${attempt}: ${failure.message}`);
        this.#logger.warn('navigation decision attempt failed', {
          provider: this.name,
          attempt,
          problem: failure.message,
        });
        if (!failure.retryable) break;
        const asked = failure.retryAfterMs;
        if (asked !== undefined && asked > retry.maxDelayMs) {
          problems.push(
            `the server asks to wait ${Math.round(asked)} ms, more than ${retry.maxDelayMs}`,
          );
          break;
        }
        if (failure.feedback !== undefined && reply !== undefined) {
          const last = messages.at(-1);
          // Keep the conversation short: one correction at a time.
          if (last?.role === 'user' && typeof last.content === 'string') messages.splice(-2, 2);
          messages.push({ role: 'assistant', content: reply.slice(0, 2000) });
          messages.push({ role: 'user', content: failure.feedback });
        } else if (attempt <= retry.maxRetries) {
          await delay(asked ?? backoffMs(retry, attempt), signal);
        }
      }
    }
    return this.#fallBack(context, signal, problems);
  }

  /** No valid decision came: the fallback decides, saying why, or the call rejects. */
  async #fallBack(
    context: DecisionContext,
    signal: AbortSignal,
    problems: string[],
  ): Promise<NavigationDecision> {
    const why = problems.join('; ');
    const fallback = this.#settings.fallback;
    if (fallback !== undefined) {
      this.#logger.warn('navigation decision falls back', { provider: this.name, why });
      const decision = await fallback.decide(context, signal);
      return {
        ...decision,
        reasoning: `[fallback ${fallback.name}: ${why}] ${decision.reasoning}`.slice(0, 2000),
      };
    }
    throw new NavigationError('PROVIDER_ERROR', `${this.name}: no valid decision (${why})`, {
      details: { problems },
    });
  }

  #userContent(context: DecisionContext, schema: Record<string, unknown>): ContentPart[] {
    return userContent(context, schema, {
      format: this.#client.format,
      sendFrame: this.wantsFrame,
      sendMapImage: this.#settings.sendMapImage,
    });
  }

  #aborted(signal: AbortSignal): NavigationError {
    return new NavigationError('ABORTED', `${this.name}: decision cancelled`, {
      cause: signal.reason,
    });
  }
}
