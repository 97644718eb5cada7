import { expect, it } from 'vitest';
import { distanceToSteps, MovePlan, rotationToSteps, StepAccumulator } from './index.js';

it('README: converts, accumulates and plans as documented', () => {
  expect(distanceToSteps(10)).toBe(2172);
  expect(rotationToSteps(90)).toEqual({ left: -1706, right: 1706 });
  const wheel = new StepAccumulator();
  let total = 0;
  for (let i = 0; i < 100; i += 1) total += wheel.add(10);
  expect(total).toBe(217299);
  const plan = new MovePlan(2172, 2172, 1024, 512);
  expect(plan.durationUs).toBe(4121094);
  expect(plan.stepsAt(2_000_000)).toEqual({ left: 1024, right: 1024 });
});
