import { normalizeAngle, stepsPerCm } from '@hal/types';
import type { HalContext } from './context.js';
import { poseData, runMotion } from './run-motion.js';

/** The checked parameters of `moveTo`: the target in metres, the speed in m/s. */
export interface MoveToTarget {
  x: number;
  y: number;
  speed?: number | undefined;
}

/**
 * m/s along the ground to wheel steps/s (undefined: top speed). The boundary has already refused
 * speeds outside the robot's slowest..top speed; the clamp only absorbs rounding.
 */
function speedStepsPerS(ctx: HalContext, mPerS: number | undefined): number | undefined {
  if (mPerS === undefined) return undefined;
  const robot = ctx.robot();
  const slowest = Math.min(robot.minSpeedStepsPerS, robot.maxSpeedStepsPerS);
  return Math.max(slowest, Math.min(robot.maxSpeedStepsPerS, mPerS * 100 * stepsPerCm(robot)));
}

/**
 * Drives to a point of the odometry frame: `rotate_deg` toward it, then `move_cm` straight along
 * the heading actually reached, in pieces no longer than one command's step limit allows.
 */
export async function moveTo(ctx: HalContext, p: MoveToTarget): Promise<Record<string, unknown>> {
  const sps = speedStepsPerS(ctx, p.speed);
  const withSpeed = <T extends object>(params: T): T =>
    sps === undefined ? params : { ...params, speed: sps };
  let pose = ctx.tracker.pose();
  let dx = p.x - pose.position.x;
  let dy = p.y - pose.position.y;
  if (Math.hypot(dx, dy) < 1e-4) return { moves: 0, pose: poseData(ctx) };
  let moves = 0;
  const turn = normalizeAngle(Math.atan2(dy, dx) - pose.rotation.yaw);
  const turnDeg = (turn * 180) / Math.PI;
  if (Math.abs(turnDeg) > 0.01) {
    await runMotion(ctx, 'rotate_deg', withSpeed({ degrees: turnDeg }));
    moves += 1;
  }
  // go straight, in pieces no longer than one command allows
  const robot = ctx.robot();
  const maxCm = (robot.maxStepsPerCommand - 1) / stepsPerCm(robot);
  for (;;) {
    pose = ctx.tracker.pose();
    dx = p.x - pose.position.x;
    dy = p.y - pose.position.y;
    // distance along the heading actually reached
    const along = (dx * Math.cos(pose.rotation.yaw) + dy * Math.sin(pose.rotation.yaw)) * 100;
    if (along < 0.01) break;
    const cm = Math.min(along, maxCm);
    await runMotion(ctx, 'move_cm', withSpeed({ left_cm: cm, right_cm: cm }));
    moves += 1;
    if (cm >= along) break;
  }
  return { moves, pose: poseData(ctx) };
}
