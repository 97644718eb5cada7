import { describe, expect, it } from 'vitest';
import { angleDifference, normalizeAngle } from './angle.js';

describe('normalizeAngle', () => {
  it('leaves an angle inside (-pi, pi] as it is', () => {
    for (const a of [0, 1, -1, Math.PI / 2, -Math.PI / 2, 3, -3]) {
      expect(normalizeAngle(a)).toBeCloseTo(a, 15);
    }
  });

  it('gives pi for both pi and -pi, so one heading has one value', () => {
    expect(normalizeAngle(Math.PI)).toBe(Math.PI);
    expect(normalizeAngle(-Math.PI)).toBe(Math.PI);
    expect(normalizeAngle(3 * Math.PI)).toBeCloseTo(Math.PI, 12);
    // -3 * Math.PI is not exactly -3 pi in floating point: it lands a rounding error off the seam.
    expect(Math.abs(normalizeAngle(-3 * Math.PI))).toBeCloseTo(Math.PI, 12);
  });

  it('wraps whole turns away, in both directions', () => {
    expect(normalizeAngle(2 * Math.PI)).toBeCloseTo(0, 15);
    expect(normalizeAngle(-Math.PI / 2 - 2 * Math.PI)).toBeCloseTo(-Math.PI / 2, 12);
    expect(normalizeAngle(0.5 + 10 * 2 * Math.PI)).toBeCloseTo(0.5, 12);
  });

  it('wraps a large angle into range', () => {
    const wrapped = normalizeAngle(1e6);
    expect(wrapped).toBeGreaterThan(-Math.PI);
    expect(wrapped).toBeLessThanOrEqual(Math.PI);
    expect(Math.cos(wrapped)).toBeCloseTo(Math.cos(1e6), 12);
    expect(Math.sin(wrapped)).toBeCloseTo(Math.sin(1e6), 12);
  });

  it('gives NaN for NaN and for an infinite angle', () => {
    expect(normalizeAngle(Number.NaN)).toBeNaN();
    expect(normalizeAngle(Number.POSITIVE_INFINITY)).toBeNaN();
    expect(normalizeAngle(Number.NEGATIVE_INFINITY)).toBeNaN();
  });
});

describe('angleDifference', () => {
  it('takes the short way across the +-pi seam', () => {
    expect(angleDifference(Math.PI - 0.1, -Math.PI + 0.1)).toBeCloseTo(-0.2, 12);
    expect(angleDifference(-Math.PI + 0.1, Math.PI - 0.1)).toBeCloseTo(0.2, 12);
  });
});
