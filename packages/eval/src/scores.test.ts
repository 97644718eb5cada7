import { describe, expect, it } from 'vitest';
import { wilson } from './scores.js';

describe('wilson', () => {
  it('gives the 95 % Wilson interval of a proportion', () => {
    expect(wilson(5, 10)).toEqual({
      successes: 5,
      trials: 10,
      rate: 0.5,
      low: 0.2366,
      high: 0.7634,
    });
    expect(wilson(0, 10)).toMatchObject({ low: 0, high: 0.2775 });
    expect(wilson(10, 10)).toMatchObject({ low: 0.7225, high: 1 });
  });

  it('refuses counts that are not a proportion', () => {
    expect(() => wilson(3, 2)).toThrow(RangeError);
    expect(() => wilson(1.5, 2)).toThrow(/integers/);
  });
});
