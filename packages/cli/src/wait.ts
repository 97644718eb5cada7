// Waiting for the command to be aborted (Ctrl-C). A pause that ends early on it is @hal/types'
// `delay(ms, signal)`, so no loop outlives its command.

/** Resolves when `signal` is aborted. */
export function aborted(signal: AbortSignal): Promise<void> {
  if (signal.aborted) return Promise.resolve();
  return new Promise((resolve) =>
    signal.addEventListener('abort', () => resolve(), { once: true }),
  );
}
