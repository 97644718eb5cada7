import { describe, expect, it } from 'vitest';
import { HalError } from '@hal/types';
import seed from '../../../tests/vectors/seed-figures.json' with { type: 'json' };
import { calculateMoveDuration, toMicros, TrapezoidalProfile, VelocityProfile } from './profile.js';

describe('calculateMoveDuration', () => {
  it('holds the specification figures (triangular 1706 steps, trapezoidal 2172 steps)', () => {
    for (const figure of seed.trapezoidal_profile_derived) {
      const ms = calculateMoveDuration(
        figure.steps,
        figure.max_speed_steps_per_s,
        figure.acceleration_steps_per_s2,
      );
      expect(ms / 1000).toBeCloseTo(figure.duration_s_approx, 3);
    }
  });

  it('is zero for no steps and symmetric in the sign of the steps', () => {
    expect(calculateMoveDuration(0, 1024, 512)).toBe(0);
    expect(calculateMoveDuration(-2172, 1024, 512)).toBe(calculateMoveDuration(2172, 1024, 512));
  });
});

describe('TrapezoidalProfile', () => {
  it('is triangular below 2 x accelSteps and reaches cruise above', () => {
    expect(new TrapezoidalProfile(1706, 1024, 512).reachesCruise).toBe(false);
    const trapezoid = new TrapezoidalProfile(2172, 1024, 512);
    expect(trapezoid.reachesCruise).toBe(true);
    expect(trapezoid.velocityAt(2.05)).toBe(1024);
  });

  it('places step times strictly increasing, the last at the duration', () => {
    for (const profile of [
      new TrapezoidalProfile(1706, 1024, 512),
      new TrapezoidalProfile(3000, 2048, 512),
    ]) {
      let previous = 0;
      for (let k = 1; k <= profile.steps; k += 1) {
        const t = profile.stepTimeUs(k);
        expect(t).toBeGreaterThan(previous);
        previous = t;
      }
      expect(previous).toBe(profile.durationUs);
      expect(profile.durationUs).toBe(toMicros(profile.durationSeconds));
    }
  });

  it('counts whole steps at any time exactly as the step times say', () => {
    const profile = new TrapezoidalProfile(2172, 1024, 512);
    for (let k = 1; k <= profile.steps; k += 37) {
      const t = profile.stepTimeUs(k);
      expect(profile.stepsDoneAt(t)).toBe(k);
      expect(profile.stepsDoneAt(t - 1)).toBe(k - 1);
    }
    expect(profile.stepsDoneAt(0)).toBe(0);
    expect(profile.stepsDoneAt(1e12)).toBe(2172);
  });

  it('has a continuous position that starts at 0, ends at the steps and agrees with velocity', () => {
    const profile = new TrapezoidalProfile(2172, 1024, 512);
    expect(profile.positionAt(0)).toBe(0);
    expect(profile.positionAt(profile.durationSeconds)).toBe(2172);
    const t = 1.3;
    const dt = 1e-6;
    expect((profile.positionAt(t + dt) - profile.positionAt(t - dt)) / (2 * dt)).toBeCloseTo(
      profile.velocityAt(t),
      2,
    );
    expect(profile.positionAt(profile.durationSeconds / 2)).toBeCloseTo(1086, 6);
  });

  it('refuses fractional or negative steps and non-positive speeds', () => {
    expect(() => new TrapezoidalProfile(1.5, 1024, 512)).toThrow(HalError);
    expect(() => new TrapezoidalProfile(-1, 1024, 512)).toThrow(/"steps"/);
    expect(() => new TrapezoidalProfile(10, 0, 512)).toThrow(/"speed"/);
    expect(() => new TrapezoidalProfile(10, 1024, Number.NaN)).toThrow(/"acceleration"/);
  });
});

describe('VelocityProfile', () => {
  it('accelerates then cruises at the speed, one step every 1/v seconds', () => {
    const profile = new VelocityProfile(1024, 512);
    expect(profile.velocityAt(1)).toBe(512);
    expect(profile.velocityAt(5)).toBe(1024);
    expect(profile.stepTime(2000) - profile.stepTime(1999)).toBeCloseTo(1 / 1024, 12);
    const t = profile.stepTimeUs(1500);
    expect(profile.stepsDoneAt(t)).toBe(1500);
    expect(profile.stepsDoneAt(t - 1)).toBe(1499);
    expect(() => new VelocityProfile(-5, 512)).toThrow(HalError);
  });
});
