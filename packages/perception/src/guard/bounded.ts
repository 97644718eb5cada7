import { HalError, withTimeout } from '@hal/types';

/** `work`'s value, or a TIMEOUT HalError naming `what` when it takes longer than `ms`. */
export async function bounded<T>(work: Promise<T>, ms: number, what: string): Promise<T> {
  const outcome = await withTimeout(work, ms);
  if (outcome === undefined) {
    work.catch(() => undefined);
    throw new HalError('TIMEOUT', `the guard got no ${what} within ${ms} ms`, {
      details: { timeoutMs: ms },
    });
  }
  return outcome.value;
}
