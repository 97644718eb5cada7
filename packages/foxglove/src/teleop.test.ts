import { HalError, V1_ROBOT, maxLinearSpeedMPerS } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { powersOfTwist } from './teleop.js';

const top = maxLinearSpeedMPerS(V1_ROBOT);

describe('powersOfTwist', () => {
  it('drives both wheels alike for a straight Twist, in proportion to the top speed', () => {
    expect(powersOfTwist({ linear: { x: top / 2 }, angular: { z: 0 } }, V1_ROBOT)).toEqual({
      left: 128,
      right: 128,
    });
    expect(powersOfTwist({ linear: { x: -top } }, V1_ROBOT)).toEqual({ left: -255, right: -255 });
  });

  it('turns counter-clockwise for a positive angular.z (REP-103): the right wheel ahead', () => {
    const { left, right } = powersOfTwist({ angular: { z: 0.5 } }, V1_ROBOT);
    expect(right).toBeGreaterThan(0);
    expect(left).toBe(-right);
  });

  it('caps a wheel at full power beyond the top speed, and takes a missing field as 0', () => {
    expect(powersOfTwist({ linear: { x: 10 * top } }, V1_ROBOT)).toEqual({ left: 255, right: 255 });
    expect(powersOfTwist({}, V1_ROBOT)).toEqual({ left: 0, right: 0 });
  });

  it('refuses what is no Twist with INVALID_PARAMETER', () => {
    for (const bad of [
      { linear: { x: 'fast' } },
      { angular: { z: Number.NaN } },
      { linear: { x: Infinity } },
    ]) {
      expect(() => powersOfTwist(bad, V1_ROBOT)).toThrow(HalError);
    }
  });
});
