import { HalError } from '@hal/types';

/** Waits for `promise` at most `ms`; past that rejects with TIMEOUT (the promise runs on). */
export function boundedWait<T>(promise: Promise<T>, ms: number): Promise<T> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new HalError('TIMEOUT', `no answer within ${ms} ms`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}
