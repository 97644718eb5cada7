// How fast the step planner answers "how many steps by now?", the simulation's inner question.
import { MovePlan } from '@hal/kinematics';
import { reportFigure } from './report/figures.js';

const plan = new MovePlan(40_960, 30_000, 1024, 512);
const queries = 2_000_000;
const stride = plan.durationUs / queries;
let checksum = 0;
const start = process.hrtime.bigint();
for (let i = 0; i < queries; i += 1) checksum += plan.stepsAt(i * stride).left;
const seconds = Number(process.hrtime.bigint() - start) / 1e9;
console.log(
  `MovePlan.stepsAt: ${(queries / seconds / 1e6).toFixed(2)} M queries/s (checksum ${checksum})`,
);
reportFigure({
  bench: 'kinematics',
  name: 'MovePlan.stepsAt (closed form)',
  value: queries / seconds / 1e6,
  unit: 'M queries/s',
  better: 'higher',
  note: 'no alternative: the firmware planner has no other implementation to compare with',
});
