/** How the loop retries a request that failed with HTTP 408, 429, 5xx, a network error or a timeout. */
export interface RetryPolicy {
  /** Attempts after the first, per model request. Default 3. */
  maxRetries: number;
  /** The first wait, ms; it doubles per attempt (with jitter). Default 500. */
  baseDelayMs: number;
  /**
   * The longest wait, ms. A server that asks (Retry-After) for a longer wait ends the run with
   * the error instead of keeping it waiting past this. Default 30000.
   */
  maxDelayMs: number;
}

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

/** The backoff before attempt `attempt + 1`: base x 2^(attempt-1), between half and all of it. */
export function backoffMs(
  policy: RetryPolicy,
  attempt: number,
  random: () => number = Math.random,
): number {
  const full = Math.min(policy.maxDelayMs, policy.baseDelayMs * 2 ** (attempt - 1));
  return Math.round(full * (0.5 + 0.5 * random()));
}

/** Waits `ms`, or less when `signal` aborts (it resolves either way). */
export function pause(ms: number, signal: AbortSignal): Promise<void> {
  return new Promise((resolve) => {
    if (signal.aborted) {
      resolve();
      return;
    }
    const done = () => {
      clearTimeout(timer);
      signal.removeEventListener('abort', done);
      resolve();
    };
    const timer = setTimeout(done, ms);
    signal.addEventListener('abort', done, { once: true });
  });
}
