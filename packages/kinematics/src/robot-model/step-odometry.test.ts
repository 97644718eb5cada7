import { integrateOdometry } from '../odometry.js';
import { MovePlan, VelocityPlan } from '../planner.js';
import { V1_ROBOT } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { StepOdometry } from './step-odometry.js';

describe('StepOdometry', () => {
  it('integrates each step as the firmware formula does, and counts the steps the plan makes', () => {
    for (const plan of [
      new MovePlan(3000, -1234, 1024, 512),
      new MovePlan(-577, -2000, 700, 512),
      new VelocityPlan(1024, 905, 512),
    ]) {
      const start = { xCm: 12, yCm: -3, headingRad: 2.5 };
      const odometry = new StepOdometry(start);
      odometry.begin(plan, V1_ROBOT);
      let pose = start;
      let before = { left: 0, right: 0 };
      // Reference: the firmware's formula over every single step, from the planner's counts.
      for (let k = 1; k <= 1900; k += 1) {
        const steps = plan.stepsAt(plan.masterStepTimeUs(k));
        pose = integrateOdometry(pose, steps.left - before.left, steps.right - before.right);
        before = steps;
      }
      odometry.walkTo(700); // in two walks: the split changes nothing
      odometry.walkTo(1900);
      expect([odometry.left, odometry.right]).toEqual([before.left, before.right]);
      expect(odometry.xCm).toBeCloseTo(pose.xCm, 9);
      expect(odometry.yCm).toBeCloseTo(pose.yCm, 9);
      expect(odometry.pose.headingRad).toBeCloseTo(pose.headingRad, 12);
    }
  });

  it('reports how far the centre moves per step: one step straight, none turning in place', () => {
    const straight = new StepOdometry({ xCm: 0, yCm: 0, headingRad: 0 });
    straight.begin(new MovePlan(100, 100, 1024, 512), V1_ROBOT);
    expect(straight.maxStepCm).toBeCloseTo((Math.PI * 6) / 4096, 12);
    const turn = new StepOdometry({ xCm: 0, yCm: 0, headingRad: 0 });
    turn.begin(new MovePlan(-100, 100, 1024, 512), V1_ROBOT);
    expect(turn.maxStepCm).toBe(0);
  });
});

describe('StepOdometry by whole periods', () => {
  it('gives the same bits walked one step at a time or in one go, and the per-step pose to a nanometre', () => {
    const plan = new VelocityPlan(1024, 905, 512); // the pattern repeats every 1024 steps
    const start = { xCm: 1, yCm: 2, headingRad: -1 };
    const oneGo = new StepOdometry(start);
    oneGo.begin(plan, V1_ROBOT);
    oneGo.walkTo(50_000);
    const stepwise = new StepOdometry(start);
    stepwise.begin(plan, V1_ROBOT);
    for (let k = 1; k <= 50_000; k += 37) stepwise.walkTo(k);
    stepwise.walkTo(50_000);
    expect([stepwise.xCm, stepwise.yCm, stepwise.pose.headingRad]).toEqual([
      oneGo.xCm,
      oneGo.yCm,
      oneGo.pose.headingRad,
    ]);
    let pose = start;
    let before = { left: 0, right: 0 };
    for (let k = 1; k <= 50_000; k += 1) {
      const steps = plan.stepsAt(plan.masterStepTimeUs(k));
      pose = integrateOdometry(pose, steps.left - before.left, steps.right - before.right);
      before = steps;
    }
    expect([oneGo.left, oneGo.right]).toEqual([before.left, before.right]);
    expect(Math.hypot(oneGo.xCm - pose.xCm, oneGo.yCm - pose.yCm)).toBeLessThan(1e-7);
    expect(Math.abs(oneGo.pose.headingRad - pose.headingRad)).toBeLessThan(1e-9);
  });
});
