import { describe, expect, it } from 'vitest';
import { passHatK } from './pass-k.js';

describe('passHatK', () => {
  it('averages C(c, k) / C(n, k) over the tasks, for k = 1 to n', () => {
    // 3 of 5: 3/5, C(3,2)/C(5,2) = 3/10, 1/10, 0, 0; 5 of 5: 1 at every k
    expect(
      passHatK([
        { successes: 3, trials: 5 },
        { successes: 5, trials: 5 },
      ]),
    ).toEqual([
      { k: 1, rate: 0.8 },
      { k: 2, rate: 0.65 },
      { k: 3, rate: 0.55 },
      { k: 4, rate: 0.5 },
      { k: 5, rate: 0.5 },
    ]);
  });

  it('tells a reliable agent from a flaky one with the same rate', () => {
    const reliable = passHatK([
      { successes: 4, trials: 4 },
      { successes: 0, trials: 4 },
    ]);
    const flaky = passHatK([
      { successes: 2, trials: 4 },
      { successes: 2, trials: 4 },
    ]);
    expect(reliable[0]?.rate).toBe(flaky[0]?.rate);
    expect(reliable.map((p) => p.rate)).toEqual([0.5, 0.5, 0.5, 0.5]);
    // C(2,2)/C(4,2) = 1/6, then 0
    expect(flaky.map((p) => p.rate)).toEqual([0.5, 0.1667, 0, 0]);
  });

  it('goes up to the fewest trials of any task, and is empty with no task', () => {
    expect(
      passHatK([
        { successes: 3, trials: 3 },
        { successes: 1, trials: 2 },
      ]).map((p) => p.k),
    ).toEqual([1, 2]);
    expect(passHatK([])).toEqual([]);
  });

  it('refuses counts that are not a task’s trials', () => {
    expect(() => passHatK([{ successes: 2, trials: 1 }])).toThrow(RangeError);
    expect(() => passHatK([{ successes: 0.5, trials: 1 }])).toThrow(/integers/);
  });
});
