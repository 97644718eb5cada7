import { describe, expect, it } from 'vitest';
import { summarize } from './stats.js';

describe('summarize', () => {
  it('gives the nearest-rank p50, p99 and the max', () => {
    const values = Array.from({ length: 100 }, (_, i) => 100 - i); // 100..1, unsorted
    expect(summarize(values)).toEqual({ samples: 100, p50Ms: 50, p99Ms: 99, maxMs: 100 });
  });

  it('gives one value as every percentile, and zeros for none', () => {
    expect(summarize([3.5])).toEqual({ samples: 1, p50Ms: 3.5, p99Ms: 3.5, maxMs: 3.5 });
    expect(summarize([])).toEqual({ samples: 0, p50Ms: 0, p99Ms: 0, maxMs: 0 });
  });
});
