import { describe, expect, it } from 'vitest';
import { getStepsPerCm } from './geometry.js';
import { integrateOdometry, OdometryIntegrator } from './odometry.js';
import { rotationToSteps } from './steps.js';

const origin = { xCm: 0, yCm: 0, headingRad: 0 };

describe('integrateOdometry (REP-103)', () => {
  it('goes +x for equal forward steps', () => {
    const pose = integrateOdometry(origin, 2172, 2172);
    expect(pose.xCm).toBeCloseTo(2172 / getStepsPerCm(), 12);
    expect(pose.yCm).toBe(0);
    expect(pose.headingRad).toBe(0);
  });

  it('turns counter-clockwise (heading grows) when the right wheel goes forward', () => {
    const turn = rotationToSteps(90);
    const pose = integrateOdometry(origin, turn.left, turn.right);
    expect(pose.headingRad).toBeCloseTo(Math.PI / 2, 2);
    expect(Math.hypot(pose.xCm, pose.yCm)).toBeLessThan(1e-9);
  });

  it('curves left (+y) on a left arc and matches the arc geometry', () => {
    const pose = integrateOdometry(origin, 1000, 2000);
    expect(pose.yCm).toBeGreaterThan(0);
    const dl = 1000 / getStepsPerCm();
    const dr = 2000 / getStepsPerCm();
    const radius = ((dl + dr) / 2 / (dr - dl)) * 10;
    const angle = (dr - dl) / 10;
    expect(pose.xCm).toBeCloseTo(radius * Math.sin(angle), 9);
    expect(pose.yCm).toBeCloseTo(radius * (1 - Math.cos(angle)), 9);
  });

  it('gives the same pose for one batch or many small steps along a constant arc', () => {
    let stepwise = origin;
    for (let i = 0; i < 100; i += 1) stepwise = integrateOdometry(stepwise, 10, 20);
    const batch = integrateOdometry(origin, 1000, 2000);
    expect(stepwise.xCm).toBeCloseTo(batch.xCm, 9);
    expect(stepwise.yCm).toBeCloseTo(batch.yCm, 9);
  });
});

describe('OdometryIntegrator', () => {
  it('integrates from absolute counters and ignores repeats', () => {
    const odo = new OdometryIntegrator();
    odo.update(2172, 2172);
    const once = odo.update(2172, 2172);
    expect(once.xCm).toBeCloseTo(2172 / getStepsPerCm(), 12);
    odo.reset({ xCm: 5, yCm: 0, headingRad: 0 }, 2172, 2172);
    expect(odo.update(2172, 2172).xCm).toBe(5);
  });
});
