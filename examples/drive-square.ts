// Plans a 20 cm square for the V1 stepper cube exactly as its firmware would execute it: each leg
// and each 90 degree turn becomes whole wheel steps (drift-free), a trapezoidal step plan, and the
// odometry pose the robot reports at the end.
import {
  integrateOdometry,
  MovePlan,
  rotationArcCm,
  StepAccumulator,
  V1_GEOMETRY,
} from '@hal/kinematics';
import type { PlanarPoseCm } from '@hal/kinematics';

const left = new StepAccumulator();
const right = new StepAccumulator();
let pose: PlanarPoseCm = { xCm: 0, yCm: 0, headingRad: 0 };
let clockUs = 0;

function run(label: string, leftCm: number, rightCm: number): void {
  const plan = new MovePlan(
    left.add(leftCm),
    right.add(rightCm),
    V1_GEOMETRY.maxSpeedStepsPerS,
    V1_GEOMETRY.accelerationStepsPerS2,
  );
  const steps = plan.stepsAt(plan.durationUs);
  pose = integrateOdometry(pose, steps.left, steps.right);
  clockUs += plan.durationUs;
  const deg = (pose.headingRad * 180) / Math.PI;
  console.log(
    `${label.padEnd(12)} steps L ${String(steps.left).padStart(6)} R ${String(steps.right).padStart(6)}` +
      `  ${(plan.durationUs / 1e6).toFixed(3)} s  ->  x ${pose.xCm.toFixed(2)} cm  y ${pose.yCm.toFixed(2)} cm  heading ${deg.toFixed(2)} deg`,
  );
}

console.log('A 20 cm square on the V1 stepper cube (4096 steps/rev, 6 cm wheels, 10 cm base):\n');
for (let side = 1; side <= 4; side += 1) {
  run(`forward ${side}`, 20, 20);
  const arc = rotationArcCm(90);
  run(`left 90 #${side}`, -arc, arc);
}
console.log(
  `\nTotal time ${(clockUs / 1e6).toFixed(2)} s; the robot ends ${Math.hypot(pose.xCm, pose.yCm).toFixed(2)} cm from where it started.`,
);
