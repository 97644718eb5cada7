import { describe, expect, it } from 'vitest';
import { intervalOverTasks, wilsonBounds } from './interval.js';
import type { TaskCount } from './interval.js';
import { wilson } from './scores.js';

/** `n` tasks of `k` trials: the first `passing` pass every trial, the rest none. */
const allOrNothing = (n: number, passing: number, k: number): TaskCount[] =>
  Array.from({ length: n }, (_, i) => ({ successes: i < passing ? k : 0, trials: k }));

describe('intervalOverTasks', () => {
  it('is about twice as wide as Wilson over the trials when each task passes all or nothing', () => {
    // 26 tasks of 5 trials, 13 passed on every seed and 13 on none: 26 observations, not 130
    const tasks = allOrNothing(26, 13, 5);
    const over = intervalOverTasks(tasks);
    const naive = wilson(65, 130);
    expect(over.method).toBe('bootstrap-tasks');
    expect(over.low).toBeLessThan(0.5);
    expect(over.high).toBeGreaterThan(0.5);
    const ratio = (over.high - over.low) / (naive.high - naive.low);
    expect(ratio).toBeGreaterThan(1.8);
    expect(ratio).toBeLessThan(2.6);
    // the textbook figure: 0.5 ± 1.96 sqrt(0.25 / 26), about ±0.19
    expect(over.low).toBeCloseTo(0.31, 1);
    expect(over.high).toBeCloseTo(0.69, 1);
  });

  it('gives the same interval for the same counts, and another for another seed', () => {
    const tasks = Array.from({ length: 17 }, (_, i) => ({
      successes: (i * 5) % 8,
      trials: 7 + (i % 3),
    }));
    expect(intervalOverTasks(tasks)).toEqual(intervalOverTasks(tasks));
    expect(intervalOverTasks(tasks, { seed: 99 })).not.toEqual(intervalOverTasks(tasks));
  });

  it('is near Wilson over the trials when the tasks differ no more than chance would make them', () => {
    // 40 tasks, each 1 success in 2 trials: all the spread is within tasks, none between them
    const tasks = [
      ...Array.from({ length: 20 }, () => ({ successes: 2, trials: 4 })),
      ...Array.from({ length: 20 }, () => ({ successes: 1, trials: 4 })),
      ...Array.from({ length: 20 }, () => ({ successes: 3, trials: 4 })),
    ];
    const over = intervalOverTasks(tasks);
    const naive = wilson(120, 240);
    expect(over.high - over.low).toBeLessThan(naive.high - naive.low);
  });

  it('falls back to Wilson over the tasks where every task scored the same', () => {
    expect(intervalOverTasks(allOrNothing(26, 26, 5))).toEqual({
      ...wilsonBounds(1, 26),
      method: 'wilson-tasks',
    });
    expect(intervalOverTasks(allOrNothing(26, 26, 5))).toMatchObject({ low: 0.8713, high: 1 });
    expect(intervalOverTasks(allOrNothing(4, 0, 2))).toMatchObject({ low: 0, high: 0.4899 });
    expect(intervalOverTasks([])).toEqual({ low: 0, high: 1, method: 'wilson-tasks' });
  });

  it('refuses counts that are not a task’s trials, and a bad number of resamples', () => {
    expect(() => intervalOverTasks([{ successes: 3, trials: 2 }])).toThrow(RangeError);
    expect(() => intervalOverTasks([{ successes: 0, trials: 0 }])).toThrow(/trials >= 1/);
    expect(() => intervalOverTasks([{ successes: 1, trials: 2 }], { resamples: 0 })).toThrow(
      /"resamples" must be a whole number of 1 or more, got 0/,
    );
  });
});
