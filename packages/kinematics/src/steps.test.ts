import { describe, expect, it } from 'vitest';
import { HalError, robotConfig } from '@hal/types';
import seed from '../../../tests/vectors/seed-figures.json' with { type: 'json' };
import { getStepsPerCm, V1_GEOMETRY, wheelCircumferenceCm } from './geometry.js';
import {
  calculateArcSpeeds,
  distanceToSteps,
  rotationArcCm,
  rotationToSteps,
  StepAccumulator,
  stepsToDistance,
  truncateSteps,
  velocityToStepsPerSecond,
} from './steps.js';

describe('geometry', () => {
  it('has the seed figures: ~18.85 cm circumference and ~217.3 steps/cm', () => {
    expect(wheelCircumferenceCm()).toBeCloseTo(seed.robot_v1.wheel_circumference_cm_approx, 2);
    expect(getStepsPerCm()).toBeCloseTo(seed.robot_v1.steps_per_cm_approx, 1);
    expect(V1_GEOMETRY.maxSpeedStepsPerS / getStepsPerCm()).toBeCloseTo(
      seed.robot_v1.max_speed_cm_per_s_approx,
      2,
    );
  });
});

describe('truncateSteps', () => {
  it('truncates toward zero', () => {
    expect(truncateSteps(1706.67)).toBe(1706);
    expect(truncateSteps(-1706.67)).toBe(-1706);
    expect(truncateSteps(0.5)).toBe(0);
  });

  it('keeps a whole number computed a hair below itself', () => {
    expect(truncateSteps(2172.9999999999995)).toBe(2173);
    expect(truncateSteps(-2172.9999999999995)).toBe(-2173);
  });
});

describe('distanceToSteps', () => {
  it('converts 10 cm to 2172 steps and is odd-symmetric', () => {
    expect(distanceToSteps(10)).toBe(2172);
    expect(distanceToSteps(-10)).toBe(-2172);
    expect(distanceToSteps(0)).toBe(0);
  });

  it('uses the geometry it is given', () => {
    const measured = robotConfig({ stepsPerRevolution: 4076 });
    expect(distanceToSteps(10, measured)).toBe(2162);
  });

  it('refuses NaN and Infinity with INVALID_PARAMETER', () => {
    expect(() => distanceToSteps(Number.NaN)).toThrow(HalError);
    expect(() => distanceToSteps(Number.POSITIVE_INFINITY)).toThrow(
      /"distanceCm" must be a finite number/,
    );
  });

  it('round-trips through stepsToDistance within one step', () => {
    for (const cm of [0.3, 1, 12.5, 99.9]) {
      expect(Math.abs(stepsToDistance(distanceToSteps(cm)) - cm)).toBeLessThan(1 / getStepsPerCm());
    }
    expect(() => stepsToDistance(Number.NaN)).toThrow(HalError);
  });
});

describe('rotationToSteps', () => {
  it('turns 90 degrees with 1706 steps per wheel, the specification figure', () => {
    const [spec] = seed.rotation;
    expect(rotationArcCm(90)).toBeCloseTo(spec?.arc_per_wheel_cm_approx ?? Number.NaN, 2);
    expect(rotationToSteps(90)).toEqual({
      left: -spec!.steps_per_wheel,
      right: spec!.steps_per_wheel,
    });
  });

  it('turns counter-clockwise for positive degrees: left wheel back, right wheel forward', () => {
    const ccw = rotationToSteps(45);
    expect(ccw.left).toBeLessThan(0);
    expect(ccw.right).toBeGreaterThan(0);
    const cw = rotationToSteps(-45);
    expect(cw.left).toBeGreaterThan(0);
    expect(cw.right).toBeLessThan(0);
  });

  it('gives zero steps (not -0) for zero degrees and refuses NaN', () => {
    expect(Object.is(rotationToSteps(0).left, 0)).toBe(true);
    expect(() => rotationToSteps(Number.NaN)).toThrow(/"degrees"/);
  });
});

describe('velocityToStepsPerSecond', () => {
  it('converts and clamps to the top speed, keeping the sign', () => {
    expect(velocityToStepsPerSecond(2)).toBeCloseTo(2 * getStepsPerCm(), 9);
    expect(velocityToStepsPerSecond(100)).toBe(1024);
    expect(velocityToStepsPerSecond(-100)).toBe(-1024);
    expect(() => velocityToStepsPerSecond(Number.NaN)).toThrow(HalError);
  });
});

describe('calculateArcSpeeds', () => {
  it('makes the inner wheel slower on a left (positive radius) arc', () => {
    const speeds = calculateArcSpeeds(30, 2);
    expect(speeds.left).toBeLessThan(speeds.right);
    expect(speeds.left).toBeGreaterThan(0);
    expect((speeds.right - speeds.left) / ((speeds.right + speeds.left) / 2)).toBeCloseTo(
      10 / 30,
      9,
    );
  });

  it('scales both wheels together at the top speed so the radius is kept', () => {
    const speeds = calculateArcSpeeds(-20, 50);
    expect(Math.max(Math.abs(speeds.left), Math.abs(speeds.right))).toBeCloseTo(1024, 9);
    expect(speeds.left / speeds.right).toBeCloseTo((-20 - 5) / (-20 + 5), 9);
  });

  it('refuses a zero radius and NaN', () => {
    expect(() => calculateArcSpeeds(0, 2)).toThrow(/radiusCm/);
    expect(() => calculateArcSpeeds(10, Number.NaN)).toThrow(/speedCmPerS/);
  });
});

describe('StepAccumulator', () => {
  it('does not drift: 100 moves of 10 cm end within one step of 1000 cm', () => {
    const acc = new StepAccumulator();
    let total = 0;
    for (let i = 0; i < 100; i += 1) total += acc.add(10);
    expect(Math.abs(total - 1000 * getStepsPerCm())).toBeLessThan(1);
    expect(acc.issued).toBe(total);
    expect(100 * distanceToSteps(10)).toBeLessThan(total - 90);
  });

  it('returns to zero after equal moves there and back', () => {
    const acc = new StepAccumulator();
    const out = acc.add(12.34);
    expect(acc.add(-12.34)).toBe(-out);
    expect(acc.issued).toBe(0);
  });

  it('forgets the carried fraction on reset, and refuses NaN without changing', () => {
    const acc = new StepAccumulator();
    acc.add(10);
    expect(() => acc.add(Number.NaN)).toThrow(HalError);
    expect(acc.issued).toBe(2172);
    acc.reset();
    expect(acc.issued).toBe(0);
    expect(acc.add(10)).toBe(2172);
  });
});
