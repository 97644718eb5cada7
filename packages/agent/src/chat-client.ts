import { AgentError, errorWithCauses } from './errors.js';
import type { ChatProvider, RetryListener } from './chat-provider.js';
import type { ChatMessage, ChatTool } from './chat-types.js';
import { parseReply } from './reply.js';
import type { AssistantReply } from './reply.js';
import { backoffMs, pause, retryableStatus, retryAfterMs } from './retry.js';
import type { RetryPolicy } from './retry.js';

/** What the client needs to reach one endpoint. */
export interface ChatClientSettings {
  /** `{baseUrl}/chat/completions`. */
  url: string;
  model: string;
  apiKey: string | undefined;
  requestTimeoutMs: number;
  retry: RetryPolicy;
  temperature: number | undefined;
  maxTokens: number | undefined;
  fetch: typeof fetch;
}

/** A failed attempt the client may retry: after `delayMs` when the server named a wait. */
interface AttemptFailure {
  error: AgentError;
  retryable: boolean;
  retryAfterMs: number | undefined;
}

/**
 * Sends one chat-completions request, retrying HTTP 408/429/5xx, network errors, timeouts and
 * unreadable replies up to `retry.maxRetries` times with exponential backoff (or the server's
 * Retry-After). Each attempt is bounded by `requestTimeoutMs`. Rejects with an AgentError, or
 * with `signal.reason` once `signal` aborts.
 */
export async function requestCompletion(
  settings: ChatClientSettings,
  body: { messages: ChatMessage[]; tools: ChatTool[] },
  step: number,
  signal: AbortSignal,
  onRetry: RetryListener,
): Promise<AssistantReply> {
  const { retry } = settings;
  for (let attempt = 1; ; attempt += 1) {
    signal.throwIfAborted();
    const failure = await attemptOnce(settings, body, step, signal);
    if ('text' in failure) return failure;
    signal.throwIfAborted();
    if (!failure.retryable || attempt > retry.maxRetries) throw failure.error;
    const asked = failure.retryAfterMs;
    if (asked !== undefined && asked > retry.maxDelayMs) {
      throw new AgentError(
        failure.error.code,
        `${failure.error.message} (the server asks to wait ${Math.round(asked)} ms, more than maxDelayMs ${retry.maxDelayMs})`,
        { details: failure.error.details ?? {}, cause: failure.error },
      );
    }
    const delayMs = asked ?? backoffMs(retry, attempt);
    const status = failure.error.details?.['status'];
    onRetry({
      attempt,
      delayMs,
      reason: failure.error.message,
      ...(typeof status === 'number' ? { status } : {}),
    });
    await pause(delayMs, signal);
  }
}

async function attemptOnce(
  settings: ChatClientSettings,
  body: { messages: ChatMessage[]; tools: ChatTool[] },
  step: number,
  signal: AbortSignal,
): Promise<AssistantReply | AttemptFailure> {
  const headers: Record<string, string> = { 'content-type': 'application/json' };
  if (settings.apiKey !== undefined && settings.apiKey !== '')
    headers['authorization'] = `Bearer ${settings.apiKey}`;
  const payload: Record<string, unknown> = {
    model: settings.model,
    messages: body.messages,
    tools: body.tools,
    tool_choice: 'auto',
  };
  if (settings.temperature !== undefined) payload['temperature'] = settings.temperature;
  if (settings.maxTokens !== undefined) payload['max_tokens'] = settings.maxTokens;
  const timeout = AbortSignal.timeout(settings.requestTimeoutMs);
  let response: Response;
  let text: string;
  try {
    response = await settings.fetch(settings.url, {
      method: 'POST',
      headers,
      body: JSON.stringify(payload),
      signal: AbortSignal.any([signal, timeout]),
    });
    text = await response.text();
  } catch (cause) {
    signal.throwIfAborted();
    if (timeout.aborted) {
      return failed(
        new AgentError('TIMEOUT', `no reply within ${settings.requestTimeoutMs} ms`, { cause }),
      );
    }
    return failed(
      new AgentError('NETWORK', `request to ${settings.url} failed: ${errorWithCauses(cause)}`, {
        cause,
        details: { url: settings.url },
      }),
    );
  }
  if (!response.ok) {
    const error = new AgentError('HTTP', httpErrorText(settings, response.status, text), {
      details: { status: response.status, url: settings.url },
    });
    return {
      error,
      retryable: retryableStatus(response.status),
      retryAfterMs: retryAfterMs(response.headers),
    };
  }
  try {
    return parseReply(JSON.parse(text), step);
  } catch (cause) {
    return failed(
      cause instanceof AgentError
        ? cause
        : new AgentError('BAD_REPLY', 'the endpoint answered with something that is not JSON', {
            cause,
          }),
    );
  }
}

/** An HTTP error: the status, the URL, what the server said, and for 401/403 what the key was. */
function httpErrorText(settings: ChatClientSettings, status: number, text: string): string {
  const said = `HTTP ${status} from ${settings.url}: ${text.slice(0, 200)}`;
  if (status !== 401 && status !== 403) return said;
  const hasKey = settings.apiKey !== undefined && settings.apiKey !== '';
  return `${said} (${hasKey ? 'the API key was refused' : 'no API key was given'})`;
}

function failed(error: AgentError): AttemptFailure {
  return { error, retryable: true, retryAfterMs: undefined };
}

/** The OpenAI-compatible chat-completions endpoint as a {@link ChatProvider}. */
export function openAIProvider(settings: ChatClientSettings): ChatProvider {
  return {
    name: `openai:${settings.model}`,
    complete: (request, turn) =>
      requestCompletion(settings, request, turn.step, turn.signal, turn.onRetry),
  };
}
