import type { RetryPolicy } from '@hal/types';

/**
 * How the loop retries a request that failed with HTTP 408, 429, 5xx, a network error or a
 * timeout: the one retry policy of `@hal/types` (exponential backoff with jitter, a cap on the
 * wait a server may ask for), re-exported here for the agent's users.
 */
export type { RetryPolicy };

/** Three retries, the first after 250-500 ms, doubling; a server may ask for up to 30 s. */
export const DEFAULT_RETRY: RetryPolicy = Object.freeze({
  maxRetries: 3,
  baseDelayMs: 500,
  maxDelayMs: 30_000,
});

/** Whether an HTTP status is worth asking again. */
export function retryableStatus(status: number): boolean {
  return status === 408 || status === 429 || status >= 500;
}

/**
 * The wait a response asks for, ms: `retry-after-ms` (OpenAI's), else `Retry-After` in seconds or
 * as an HTTP date. Undefined when it asks for none or the header is unreadable.
 */
export function retryAfterMs(headers: Headers, now: number = Date.now()): number | undefined {
  const ms = Number(headers.get('retry-after-ms') ?? Number.NaN);
  if (Number.isFinite(ms) && ms >= 0) return ms;
  const value = headers.get('retry-after');
  if (value === null || value.trim() === '') return undefined;
  const seconds = Number(value);
  if (Number.isFinite(seconds)) return seconds >= 0 ? seconds * 1000 : undefined;
  const date = Date.parse(value);
  return Number.isFinite(date) ? Math.max(0, date - now) : undefined;
}
