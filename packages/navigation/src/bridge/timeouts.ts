/** What {@link withTimeout} settles with when time runs out. */
export const TIMED_OUT: unique symbol = Symbol('timed out');

/**
 * Waits for `promise` for at most `ms` milliseconds: resolves with its value, or with
 * {@link TIMED_OUT} when the time runs out first (the promise is left to settle on its own; a
 * later rejection of it is swallowed). Rejections before the deadline pass through.
 */
export function withTimeout<T>(promise: Promise<T>, ms: number): Promise<T | typeof TIMED_OUT> {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => resolve(TIMED_OUT), ms);
    promise.then(
      (value) => {
        clearTimeout(timer);
        resolve(value);
      },
      (error: unknown) => {
        clearTimeout(timer);
        reject(error);
      },
    );
  });
}
