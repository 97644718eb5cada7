import { describe, expect, it } from 'vitest';
import { HalError } from '@hal/types';
import { MovePlan, VelocityPlan } from './planner.js';

describe('MovePlan', () => {
  it('finishes both wheels together on an arc, the slower wheel by Bresenham', () => {
    const plan = new MovePlan(1000, 2172, 1024, 512);
    expect(plan.leftIsMaster).toBe(false);
    expect(plan.stepsAt(plan.durationUs)).toEqual({ left: 1000, right: 2172 });
    expect(plan.stepsAt(plan.durationUs - 1).right).toBe(2171);
    const halfway = plan.stepsAt(plan.durationUs / 2);
    expect(halfway.left).toBe(Math.floor((halfway.right * 1000) / 2172));
  });

  it('drives an in-place turn with opposite wheels of equal counts at every instant', () => {
    const plan = new MovePlan(-1706, 1706, 1024, 512);
    for (const t of [0, 100_000, 1_000_000, 2_500_000, plan.durationUs]) {
      const steps = plan.stepsAt(t);
      expect(steps.left + steps.right).toBe(0);
    }
    expect(plan.stepsAt(plan.durationUs)).toEqual({ left: -1706, right: 1706 });
    expect(plan.velocityAt(1_000_000)).toEqual({ left: -512, right: 512 });
  });

  it('makes no steps for an empty move', () => {
    const plan = new MovePlan(0, 0, 1024, 512);
    expect(plan.durationUs).toBe(0);
    expect(plan.stepsAt(5_000_000)).toEqual({ left: 0, right: 0 });
  });

  it('refuses fractional steps', () => {
    expect(() => new MovePlan(1.5, 0, 1024, 512)).toThrow(HalError);
  });
});

describe('VelocityPlan', () => {
  it('runs endlessly with the slave wheel at its speed ratio', () => {
    const plan = new VelocityPlan(1024, -512, 512);
    expect(plan.durationUs).toBe(Number.POSITIVE_INFINITY);
    const steps = plan.stepsAt(10_000_000);
    expect(steps.left).toBeGreaterThan(9000);
    expect(steps.right).toBe(-Math.floor(steps.left / 2));
    expect(plan.velocityAt(10_000_000)).toEqual({ left: 1024, right: -512 });
  });

  it('stands still at zero speeds and refuses fractional speeds', () => {
    expect(new VelocityPlan(0, 0, 512).stepsAt(1e9)).toEqual({ left: 0, right: 0 });
    expect(() => new VelocityPlan(10.5, 0, 512)).toThrow(/whole steps\/s/);
  });
});

describe('StepPlan master schedule', () => {
  it('gives the master step count and step times that stepsAt is made of, for a move and a drive', () => {
    const plans = [new MovePlan(-700, 1500, 900, 512), new VelocityPlan(800, -300, 512)];
    for (const plan of plans) {
      for (const k of [1, 2, 50, 461, 700, 1499]) {
        const t = plan.masterStepTimeUs(k);
        expect(plan.masterStepsAt(t)).toBe(k);
        expect(plan.masterStepsAt(t - 1)).toBe(k - 1);
        const slave = Math.floor((k * plan.slaveTerm) / plan.masterTerm);
        const steps = plan.stepsAt(t);
        const [master, other] = plan.leftIsMaster
          ? [steps.left, steps.right]
          : [steps.right, steps.left];
        expect(Math.abs(master)).toBe(k);
        expect(Math.abs(other)).toBe(slave);
      }
    }
    expect([plans[0]?.leftSign, plans[0]?.rightSign]).toEqual([-1, 1]);
    expect([plans[1]?.leftSign, plans[1]?.rightSign]).toEqual([1, -1]);
  });
});
