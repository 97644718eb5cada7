import { integrateOdometry, MovePlan, VelocityPlan } from '@hal/kinematics';
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
