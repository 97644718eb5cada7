import { normalizeAngle, stepsPerCm } from '@hal/types';
import type { LocomotionInterface, Pose } from '@hal/types';
import type { MotionReport } from '../robot/motion-report.js';
import type { SimRobot } from '../robot/sim-robot.js';
import { checkInsideArena } from './arena-bounds.js';
import { awaitMotion, poseData } from './await-motion.js';
import type { HalContext } from './context.js';

/** A finished move's result data: its id, the steps it made, its planned duration, the pose. */
function motionData(report: MotionReport, robot: SimRobot): Record<string, unknown> {
  return {
    moveId: report.moveId,
    leftSteps: report.doneLeft,
    rightSteps: report.doneRight,
    plannedDurationMs: Math.ceil(report.durationUs / 1000),
    pose: poseData(robot),
  };
}

/**
 * m/s along the ground to master-wheel steps/s (undefined: top speed). The boundary has already
 * refused speeds outside the robot's slowest..top speed; the clamp only absorbs rounding.
 */
function wheelSpeed(robot: SimRobot, speedMPerS: number | undefined): number | undefined {
  if (speedMPerS === undefined) return undefined;
  const config = robot.config;
  const slowest = Math.min(config.minSpeedStepsPerS, config.maxSpeedStepsPerS);
  const sps = speedMPerS * 100 * stepsPerCm(config);
  return Math.max(slowest, Math.min(config.maxSpeedStepsPerS, sps));
}

/**
 * The simulated robot's locomotion: each call is the firmware command PhysicalHAL sends for it
 * (docs/simulation.md), executed by the robot and waited for on the HAL's clock.
 */
export function createLocomotion(ctx: HalContext): LocomotionInterface {
  const b = ctx.boundary;
  const straight = async (cm: number): Promise<Record<string, unknown>> => {
    const report = await awaitMotion(ctx, ctx.robot().moveCm(cm, cm));
    return motionData(report, ctx.robot());
  };
  return {
    drive: (left, right, durationMs) =>
      b.call('drive', { left, right, durationMs }, async (p) => {
        const max = ctx.robot().config.maxSpeedStepsPerS;
        const leftSps = Math.trunc((p.left / 255) * max);
        const rightSps = Math.trunc((p.right / 255) * max);
        const ms = p.durationMs === undefined ? undefined : Math.max(1, Math.round(p.durationMs));
        const handle = ctx.robot().drive(leftSps, rightSps, ms);
        if (handle === undefined) {
          return { leftSps, rightSps, speedClamped: false, running: false };
        }
        const data = {
          moveId: handle.report.moveId,
          leftSps: handle.report.leftSps,
          rightSps: handle.report.rightSps,
          speedClamped: handle.report.speedClamped,
        };
        if (ms === undefined) {
          ctx.events.emit('motionStarted', { ...handle.report });
          void handle.finished.then((r) => ctx.events.emit('motionFinished', { ...r }));
          return { ...data, running: true };
        }
        const report = await awaitMotion(ctx, handle);
        return {
          ...data,
          running: false,
          leftSteps: report.doneLeft,
          rightSteps: report.doneRight,
        };
      }),
    moveTo: (x, y, z, speed) =>
      b.call('moveTo', { x, y, z, speed }, async (p) => {
        // The same commands PhysicalHAL sends: turn toward the point, then straight moves
        // along the heading reached, each no longer than one command allows.
        const robot = ctx.robot();
        checkInsideArena(ctx.world, robot, p.x, p.y);
        const sps = wheelSpeed(robot, p.speed);
        // planned from the pose the robot reports, as PhysicalHAL plans from its odometry
        let pose = robot.reportedPose;
        let dx = p.x - pose.x;
        let dy = p.y - pose.y;
        if (Math.hypot(dx, dy) < 1e-4) return { moves: 0, pose: poseData(ctx.robot()) };
        let moves = 0;
        const turnDeg = (normalizeAngle(Math.atan2(dy, dx) - pose.yaw) * 180) / Math.PI;
        if (Math.abs(turnDeg) > 0.01) {
          await awaitMotion(ctx, robot.rotateDeg(turnDeg, sps));
          moves += 1;
        }
        const maxCm = (robot.config.maxStepsPerCommand - 1) / stepsPerCm(robot.config);
        for (;;) {
          pose = robot.reportedPose;
          dx = p.x - pose.x;
          dy = p.y - pose.y;
          const along = (dx * Math.cos(pose.yaw) + dy * Math.sin(pose.yaw)) * 100;
          if (along < 0.01) break;
          const cm = Math.min(along, maxCm);
          await awaitMotion(ctx, robot.moveCm(cm, cm, sps));
          moves += 1;
          if (cm >= along) break;
        }
        return { moves, pose: poseData(ctx.robot()) };
      }),
    rotate: (direction, degrees) =>
      b.call('rotate', { direction, degrees }, async (p) => {
        const signed = p.direction === 'left' ? p.degrees : -p.degrees;
        const report = await awaitMotion(ctx, ctx.robot().rotateDeg(signed));
        return motionData(report, ctx.robot());
      }),
    moveForward: (distanceCm) =>
      b.call('moveForward', { distanceCm }, async (p) => straight(p.distanceCm)),
    moveBackward: (distanceCm) =>
      b.call('moveBackward', { distanceCm }, async (p) => straight(-p.distanceCm)),
    stop: () =>
      b.call('stop', {}, async () => {
        const stopped = ctx.robot().stop();
        return { stopped, pose: poseData(ctx.robot()) };
      }),
    getPose: () =>
      b.read('getPose', {}, (): Pose => {
        const r = ctx.robot();
        const v = r.velocity();
        const p = r.reportedPose;
        return {
          position: { x: p.x, y: p.y, z: 0 },
          rotation: { yaw: p.yaw, pitch: 0, roll: 0 },
          velocity: { linear: v.linear, angular: v.angular },
        };
      }),
  };
}
