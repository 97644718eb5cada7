import { normalizeAngle, stepsPerCm } from '@hal/types';
import type {
  HalBoundary,
  LocomotionInterface,
  MotionDone,
  Pose,
  RobotConfig,
  RobotPort,
} from '@hal/types';

/** The `drive()` power that means full speed. */
export const MAX_POWER = 255;

/** A `drive()` power, -255..255, as signed wheel steps/s: truncated toward zero, as the firmware does. */
export function powerToStepsPerS(power: number, config: RobotConfig): number {
  return Math.trunc((power / MAX_POWER) * config.maxSpeedStepsPerS);
}

/**
 * m/s along the ground to wheel steps/s (undefined: top speed). The boundary has already refused
 * speeds outside the robot's slowest..top speed; the clamp only absorbs rounding.
 */
export function groundSpeedToStepsPerS(
  config: RobotConfig,
  mPerS: number | undefined,
): number | undefined {
  if (mPerS === undefined) return undefined;
  const slowest = Math.min(config.minSpeedStepsPerS, config.maxSpeedStepsPerS);
  return Math.max(slowest, Math.min(config.maxSpeedStepsPerS, mPerS * 100 * stepsPerCm(config)));
}

/** The pose as result data: metres and radians, the frame of the robot's odometry. */
export function poseData(pose: Pose): Record<string, number> {
  return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
}

function motionData(done: MotionDone, port: RobotPort): Record<string, unknown> {
  return { ...done, pose: poseData(port.pose()) };
}

/**
 * Drives to a point of the odometry frame with the commands the robot understands: a rotation
 * toward it, then straight moves along the heading actually reached, each no longer than one
 * command's step limit allows. Planned from the pose the robot's odometry gives.
 */
async function moveTo(
  port: RobotPort,
  p: { x: number; y: number; speed?: number | undefined },
): Promise<Record<string, unknown>> {
  port.checkTarget?.(p.x, p.y);
  const speedStepsPerS = groundSpeedToStepsPerS(port.config(), p.speed);
  let pose = port.pose();
  let dx = p.x - pose.position.x;
  let dy = p.y - pose.position.y;
  if (Math.hypot(dx, dy) < 1e-4) return { moves: 0, pose: poseData(pose) };
  let moves = 0;
  const turnDeg = (normalizeAngle(Math.atan2(dy, dx) - pose.rotation.yaw) * 180) / Math.PI;
  if (Math.abs(turnDeg) > 0.01) {
    await port.motion({ kind: 'rotate', degrees: turnDeg, speedStepsPerS });
    moves += 1;
  }
  const config = port.config();
  const maxCm = (config.maxStepsPerCommand - 1) / stepsPerCm(config);
  for (;;) {
    pose = port.pose();
    dx = p.x - pose.position.x;
    dy = p.y - pose.position.y;
    // distance along the heading actually reached
    const along = (dx * Math.cos(pose.rotation.yaw) + dy * Math.sin(pose.rotation.yaw)) * 100;
    if (along < 0.01) break;
    const cm = Math.min(along, maxCm);
    await port.motion({ kind: 'move', leftCm: cm, rightCm: cm, speedStepsPerS });
    moves += 1;
    if (cm >= along) break;
  }
  return { moves, pose: poseData(port.pose()) };
}

/**
 * Driving the robot: each call is the firmware command it stands for (`moveTo` a few), resolved
 * when the robot reports the motion ended; but for an endless `drive`, which runs on.
 */
export function createLocomotion(b: HalBoundary, port: RobotPort): LocomotionInterface {
  const straight = async (cm: number) =>
    motionData(await port.motion({ kind: 'move', leftCm: cm, rightCm: cm }), port);
  return {
    moveForward: (distanceCm) =>
      b.call('moveForward', { distanceCm }, (p) => straight(p.distanceCm)),
    moveBackward: (distanceCm) =>
      b.call('moveBackward', { distanceCm }, (p) => straight(-p.distanceCm)),
    rotate: (direction, degrees) =>
      b.call('rotate', { direction, degrees }, async (p) => {
        const signed = p.direction === 'left' ? p.degrees : -p.degrees;
        return motionData(await port.motion({ kind: 'rotate', degrees: signed }), port);
      }),
    drive: (left, right, durationMs) =>
      b.call('drive', { left, right, durationMs }, async (p) => {
        const config = port.config();
        const ms = p.durationMs === undefined ? undefined : Math.max(1, Math.round(p.durationMs));
        const done = await port.drive(
          powerToStepsPerS(p.left, config),
          powerToStepsPerS(p.right, config),
          ms,
        );
        return { ...done };
      }),
    moveTo: (x, y, z, speed) => b.call('moveTo', { x, y, z, speed }, (p) => moveTo(port, p)),
    stop: () =>
      b.call('stop', {}, async () => {
        const stopped = await port.stop();
        return { stopped, pose: poseData(port.pose()) };
      }),
    getPose: () => b.read('getPose', {}, (): Pose => port.pose()),
  };
}
