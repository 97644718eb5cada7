// The one vocabulary of waiting: a bounded wait (`raceTimer`, and `deadline`/`withTimeout` on
// it), a pause an abort cuts short (`delay`) and the retry backoff (`RetryPolicy`,
// `backoffMs`). Every wait in the repository is one of these, so each keeps a timeout and its
// error says what timed out and after how long.
import { HalError } from '../errors.js';

/** The timers a wait runs on: the runtime's own by default, a scheduler's or a fake in tests. */
export interface Timers {
  setTimeout(fn: () => void, ms: number): unknown;
  clearTimeout(handle: unknown): void;
}

/** The runtime's timers (Node and browsers). */
export const realTimers: Timers = {
  setTimeout: (fn, ms) => globalThis.setTimeout(fn, ms),
  clearTimeout: (handle) =>
    globalThis.clearTimeout(handle as ReturnType<typeof globalThis.setTimeout>),
};

/**
 * Settles as `work` does, or with `expire()` once `ms` have passed, whichever comes first:
 * `expire` returns the value to resolve with, or throws the error to reject with. A rejection of
 * `work` before then passes through; one after is ignored (the work runs on, no longer waited
 * for). The timer never outlives the wait.
 */
export function raceTimer<T, U>(
  work: Promise<T>,
  ms: number,
  expire: () => U,
  timers: Timers = realTimers,
): Promise<T | U> {
  return new Promise<T | U>((resolve, reject) => {
    let settled = false;
    const handle = timers.setTimeout(() => {
      if (settled) return;
      settled = true;
      try {
        resolve(expire());
      } catch (error) {
        reject(error);
      }
    }, ms);
    work.then(
      (value) => {
        if (settled) return;
        settled = true;
        timers.clearTimeout(handle);
        resolve(value);
      },
      (error: unknown) => {
        if (settled) return;
        settled = true;
        timers.clearTimeout(handle);
        reject(error);
      },
    );
  });
}

/** The error of a wait that ran out: TIMEOUT, saying what and after how long. */
export function timeoutError(what: string, ms: number): HalError {
  return new HalError('TIMEOUT', `${what} did not finish within ${ms} ms`, {
    details: { timeoutMs: ms },
  });
}

/**
 * Resolves as `work` does, or rejects once `ms` have passed: with `onTimeout()` when given (a
 * function, so the error is built only when needed), else with {@link timeoutError}(`what`).
 */
export function deadline<T>(
  work: Promise<T>,
  ms: number,
  onTimeout: string | (() => Error),
  timers: Timers = realTimers,
): Promise<T> {
  return raceTimer(
    work,
    ms,
    (): never => {
      throw typeof onTimeout === 'string' ? timeoutError(onTimeout, ms) : onTimeout();
    },
    timers,
  );
}

/**
 * Resolves `{ value }` once `work` does, or `undefined` once `ms` have passed, whichever comes
 * first; a rejection of `work` before then passes through. The timer never outlives the wait.
 */
export function withTimeout<T>(
  work: Promise<T>,
  ms: number,
  timers: Timers = realTimers,
): Promise<{ value: T } | undefined> {
  return raceTimer(
    work.then((value) => ({ value })),
    ms,
    () => undefined,
    timers,
  );
}

/** Waits `ms`, or less when `signal` aborts (it resolves either way, never rejects). */
export function delay(
  ms: number,
  signal?: AbortSignal,
  timers: Timers = realTimers,
): Promise<void> {
  return new Promise((resolve) => {
    if (signal?.aborted === true) {
      resolve();
      return;
    }
    const done = (): void => {
      timers.clearTimeout(handle);
      signal?.removeEventListener('abort', done);
      resolve();
    };
    const handle = timers.setTimeout(done, ms);
    signal?.addEventListener('abort', done, { once: true });
  });
}

/** How a caller retries a request that failed in a way worth asking again. */
export interface RetryPolicy {
  /** Attempts after the first. */
  maxRetries: number;
  /** The first wait, ms; it doubles per attempt (with jitter). */
  baseDelayMs: number;
  /**
   * The longest wait, ms. A server that asks (Retry-After) for a longer wait ends the attempts
   * with its error instead of keeping the caller waiting past this.
   */
  maxDelayMs: number;
}

/**
 * The backoff before attempt `attempt + 1` (`attempt` counts from 1): base x 2^(attempt-1),
 * capped at `maxDelayMs`, between half and all of it (`random` in [0, 1) picks where).
 */
export function backoffMs(
  policy: Pick<RetryPolicy, 'baseDelayMs' | 'maxDelayMs'>,
  attempt: number,
  random: () => number = Math.random,
): number {
  const full = Math.min(policy.maxDelayMs, policy.baseDelayMs * 2 ** (attempt - 1));
  return Math.round(full * (0.5 + 0.5 * random()));
}
