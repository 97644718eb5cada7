import { describe, expect, it } from 'vitest';
import { SteppedScheduler } from './scheduler.js';

describe('SteppedScheduler', () => {
  it('fires timers in time order when advanced, at their own due time', () => {
    const s = new SteppedScheduler();
    const fired: Array<[string, number]> = [];
    s.setTimeout(() => fired.push(['b', s.now()]), 20);
    s.setTimeout(() => fired.push(['a', s.now()]), 10);
    const cancelled = s.setTimeout(() => fired.push(['x', s.now()]), 15);
    s.clearTimeout(cancelled);
    s.advanceTo(5);
    expect(fired).toEqual([]);
    s.advanceTo(25);
    expect(fired).toEqual([
      ['a', 10],
      ['b', 20],
    ]);
    expect(s.now()).toBe(25);
  });

  it('fires a timer set by a firing timer when it falls within the same advance', () => {
    const s = new SteppedScheduler();
    const fired: number[] = [];
    const tick = (): void => {
      fired.push(s.now());
      if (fired.length < 3) s.setTimeout(tick, 10);
    };
    s.setTimeout(tick, 10);
    s.advanceBy(100);
    expect(fired).toEqual([10, 20, 30]);
    expect(s.pendingCount).toBe(0);
  });

  it('never moves backwards and ignores a non-finite time', () => {
    const s = new SteppedScheduler(50);
    s.advanceTo(10);
    s.advanceTo(Number.NaN);
    expect(s.now()).toBe(50);
  });
});
