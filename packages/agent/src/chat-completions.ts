import { backoffMs, delay } from '@hal/types';
import type { RetryPolicy } from '@hal/types';
import { AgentError, errorWithCauses } from './errors.js';
import type { RetryListener } from './chat-provider.js';
import { retryableStatus, retryAfterMs } from './retry.js';

/**
 * One OpenAI-compatible chat-completions endpoint: where it is, the key, and how requests to it
 * are bounded and retried. The agent's client and navigation's LLM provider both go through it.
 */
export interface ChatEndpoint {
  /** `{baseUrl}/chat/completions`. */
  url: string;
  apiKey: string | undefined;
  /** Time allowed for one HTTP request, ms. */
  requestTimeoutMs: number;
  /** Retries of HTTP 408/429/5xx, network errors, timeouts and unreadable replies. */
  retry: RetryPolicy;
  fetch: typeof fetch;
}

/** A failed attempt the client may retry: after `retryAfterMs` when the server named a wait. */
interface AttemptFailure {
  failed: true;
  error: AgentError;
  retryable: boolean;
  retryAfterMs: number | undefined;
}

/**
 * POSTs `payload` to the endpoint and answers `read(reply JSON)`, retrying HTTP 408/429/5xx,
 * network errors, timeouts and unreadable replies (a reply that is not JSON, or one `read`
 * throws on) up to `retry.maxRetries` times with exponential backoff, or after
 * the wait the server asks for (`retry-after-ms`, `Retry-After`). A server that asks for longer
 * than `retry.maxDelayMs` ends the request with its error. Each attempt is bounded by
 * `requestTimeoutMs`. Rejects with an AgentError (an HTTP error carries `status`, `url` and,
 * when the server named one, `retryAfterMs` in `details`), or with `signal.reason` once
 * `signal` aborts.
 */
export async function postChatCompletion<T>(
  endpoint: ChatEndpoint,
  payload: Record<string, unknown>,
  read: (reply: unknown) => T,
  signal: AbortSignal,
  onRetry: RetryListener,
): Promise<T> {
  const { retry } = endpoint;
  for (let attempt = 1; ; attempt += 1) {
    signal.throwIfAborted();
    const outcome = await attemptOnce(endpoint, payload, read, signal);
    if (!isFailure(outcome)) return outcome.value;
    signal.throwIfAborted();
    if (!outcome.retryable || attempt > retry.maxRetries) throw outcome.error;
    const asked = outcome.retryAfterMs;
    if (asked !== undefined && asked > retry.maxDelayMs) {
      throw new AgentError(
        outcome.error.code,
        `${outcome.error.message} (the server asks to wait ${Math.round(asked)} ms, more than maxDelayMs ${retry.maxDelayMs})`,
        { details: outcome.error.details ?? {}, cause: outcome.error },
      );
    }
    const delayMs = asked ?? backoffMs(retry, attempt);
    const status = outcome.error.details?.['status'];
    onRetry({
      attempt,
      delayMs,
      reason: outcome.error.message,
      ...(typeof status === 'number' ? { status } : {}),
    });
    await delay(delayMs, signal);
  }
}

function isFailure<T>(outcome: { value: T } | AttemptFailure): outcome is AttemptFailure {
  return 'failed' in outcome;
}

async function attemptOnce<T>(
  endpoint: ChatEndpoint,
  payload: Record<string, unknown>,
  read: (reply: unknown) => T,
  signal: AbortSignal,
): Promise<{ value: T } | AttemptFailure> {
  const headers: Record<string, string> = { 'content-type': 'application/json' };
  if (endpoint.apiKey !== undefined && endpoint.apiKey !== '')
    headers['authorization'] = `Bearer ${endpoint.apiKey}`;
  const timeout = AbortSignal.timeout(endpoint.requestTimeoutMs);
  let response: Response;
  let text: string;
  try {
    response = await endpoint.fetch(endpoint.url, {
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
        new AgentError('TIMEOUT', `no reply within ${endpoint.requestTimeoutMs} ms`, { cause }),
      );
    }
    return failed(
      new AgentError('NETWORK', `request to ${endpoint.url} failed: ${errorWithCauses(cause)}`, {
        cause,
        details: { url: endpoint.url },
      }),
    );
  }
  if (!response.ok) {
    const waitMs = retryAfterMs(response.headers);
    const error = new AgentError('HTTP', httpErrorText(endpoint, response.status, text), {
      details: {
        status: response.status,
        url: endpoint.url,
        ...(waitMs === undefined ? {} : { retryAfterMs: waitMs }),
      },
    });
    return {
      failed: true,
      error,
      retryable: retryableStatus(response.status),
      retryAfterMs: waitMs,
    };
  }
  try {
    return { value: read(JSON.parse(text)) };
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
function httpErrorText(endpoint: ChatEndpoint, status: number, text: string): string {
  const said = `HTTP ${status} from ${endpoint.url}: ${text.slice(0, 200)}`;
  if (status !== 401 && status !== 403) return said;
  const hasKey = endpoint.apiKey !== undefined && endpoint.apiKey !== '';
  return `${said} (${hasKey ? 'the API key was refused' : 'no API key was given'})`;
}

function failed(error: AgentError): AttemptFailure {
  return { failed: true, error, retryable: true, retryAfterMs: undefined };
}
