import { describe, expect, it } from 'vitest';
import { withTimeout } from './with-timeout.js';

describe('withTimeout', () => {
  it('gives the value of work that ends in time, undefined for work that does not', async () => {
    expect(await withTimeout(Promise.resolve(0), 1000)).toEqual({ value: 0 });
    expect(await withTimeout(new Promise<number>(() => undefined), 10)).toBeUndefined();
  });

  it('passes a rejection on', async () => {
    await expect(withTimeout(Promise.reject(new Error('refused')), 1000)).rejects.toThrow(
      'refused',
    );
  });
});
