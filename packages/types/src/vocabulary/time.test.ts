import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { errorMessage, HalError } from '../errors.js';
import { backoffMs, deadline, delay, raceTimer, withTimeout } from './time.js';
import type { Timers } from './time.js';

const never = <T>(): Promise<T> => new Promise<T>(() => undefined);

describe('time', () => {
  beforeEach(() => {
    vi.useFakeTimers();
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  describe('withTimeout', () => {
    it('gives the value of work that ends in time, undefined for work that does not', async () => {
      expect(await withTimeout(Promise.resolve(0), 1000)).toEqual({ value: 0 });
      const late = withTimeout(never<number>(), 10);
      await vi.advanceTimersByTimeAsync(10);
      expect(await late).toBeUndefined();
    });

    it('passes a rejection on', async () => {
      await expect(withTimeout(Promise.reject(new Error('refused')), 1000)).rejects.toThrow(
        'refused',
      );
    });

    it('leaves no timer behind once the work has ended', async () => {
      await withTimeout(Promise.resolve(1), 60_000);
      expect(vi.getTimerCount()).toBe(0);
    });
  });

  describe('deadline', () => {
    it('rejects with TIMEOUT saying what timed out and after how long', async () => {
      const wait = deadline(never(), 250, 'the hello');
      const outcome = expect(wait).rejects.toThrow('the hello did not finish within 250 ms');
      await vi.advanceTimersByTimeAsync(250);
      await outcome;
      const error = await wait.catch((thrown: unknown) => thrown);
      expect(error).toBeInstanceOf(HalError);
      expect((error as HalError).code).toBe('TIMEOUT');
      expect((error as HalError).details).toEqual({ timeoutMs: 250 });
    });

    it("rejects with the caller's own error when it names one", async () => {
      const wait = deadline(never(), 5, () => new RangeError('too slow'));
      const outcome = expect(wait).rejects.toThrow(RangeError);
      await vi.advanceTimersByTimeAsync(5);
      await outcome;
    });

    it('resolves with the work and ignores a rejection that comes after the timeout', async () => {
      expect(await deadline(Promise.resolve('ok'), 5, 'x')).toBe('ok');
      let fail: (error: Error) => void = () => undefined;
      const work = new Promise<never>((_, reject) => (fail = reject));
      const wait = deadline(work, 5, 'x');
      const outcome = expect(wait).rejects.toThrow('x did not finish within 5 ms');
      await vi.advanceTimersByTimeAsync(5);
      fail(new Error('late'));
      await outcome;
    });
  });

  describe('raceTimer', () => {
    it('runs on the timers it is given', async () => {
      let fire: () => void = () => undefined;
      const cleared: unknown[] = [];
      const timers: Timers = {
        setTimeout: (fn) => {
          fire = fn;
          return 'handle';
        },
        clearTimeout: (handle) => cleared.push(handle),
      };
      const expired = raceTimer(never(), 1000, () => 'expired', timers);
      fire();
      expect(await expired).toBe('expired');
      await raceTimer(Promise.resolve(1), 1000, () => 0, timers);
      expect(cleared).toEqual(['handle']);
    });
  });

  describe('delay', () => {
    it('waits the time, or less when the signal aborts', async () => {
      let done = false;
      void delay(100).then(() => (done = true));
      await vi.advanceTimersByTimeAsync(99);
      expect(done).toBe(false);
      await vi.advanceTimersByTimeAsync(1);
      expect(done).toBe(true);

      const abort = new AbortController();
      const cut = delay(60_000, abort.signal);
      abort.abort();
      await cut;
      expect(vi.getTimerCount()).toBe(0);
      abort.abort();
      await delay(60_000, abort.signal);
    });
  });

  describe('backoffMs', () => {
    it('doubles from the base, capped, between half and all of the wait', () => {
      const policy = { baseDelayMs: 500, maxDelayMs: 3000 };
      expect(backoffMs(policy, 1, () => 0)).toBe(250);
      expect(backoffMs(policy, 1, () => 0.999_999)).toBe(500);
      expect(backoffMs(policy, 3, () => 0.999_999)).toBe(2000);
      expect(backoffMs(policy, 10, () => 0.999_999)).toBe(3000);
    });
  });
});

describe('errorMessage', () => {
  it("gives an Error's message and anything else's string form", () => {
    expect(errorMessage(new TypeError('bad'))).toBe('bad');
    expect(errorMessage('plain')).toBe('plain');
    expect(errorMessage(42)).toBe('42');
  });
});
