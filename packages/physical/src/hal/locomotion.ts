import { isHalError } from '@hal/types';
import type { LocomotionInterface, Pose } from '@hal/types';
import type { RequestParams } from '../protocol/schemas.js';
import type { HalContext } from './context.js';
import { unacknowledgedStop, unlessLinkLost } from './lost-link.js';
import { moveTo } from './move-to.js';
import { awaitMotion, poseData, runMotion, sendMotion } from './run-motion.js';

/** The `drive()` power that means full speed. */
const MAX_POWER = 255;

/**
 * Driving the robot: each call sends one motion command (`moveTo` a few) and, but for an endless
 * `drive`, resolves when `get_status` reports the motion finished. A motion call that loses the
 * link sends a stop and fails with NOT_CONNECTED saying whether the robot acknowledged it; a
 * `stop()` the robot does not acknowledge fails with NOT_CONNECTED (never claims the stop).
 */
export function createLocomotion(ctx: HalContext): LocomotionInterface {
  const b = ctx.boundary;
  const straight = (cm: number) =>
    unlessLinkLost(ctx, () => runMotion(ctx, 'move_cm', { left_cm: cm, right_cm: cm }));
  return {
    moveForward: (distanceCm) =>
      b.call('moveForward', { distanceCm }, (p) => straight(p.distanceCm)),
    moveBackward: (distanceCm) =>
      b.call('moveBackward', { distanceCm }, (p) => straight(-p.distanceCm)),
    rotate: (direction, degrees) =>
      b.call('rotate', { direction, degrees }, (p) =>
        unlessLinkLost(ctx, () =>
          runMotion(ctx, 'rotate_deg', {
            degrees: p.direction === 'left' ? p.degrees : -p.degrees,
          }),
        ),
      ),
    drive: (left, right, durationMs) =>
      b.call('drive', { left, right, durationMs }, (p) =>
        unlessLinkLost(ctx, async () => {
          const max = ctx.robot().maxSpeedStepsPerS;
          const leftSps = Math.trunc((p.left / MAX_POWER) * max);
          const rightSps = Math.trunc((p.right / MAX_POWER) * max);
          const params: RequestParams['drive'] = { left_sps: leftSps, right_sps: rightSps };
          if (p.durationMs !== undefined)
            params.duration_ms = Math.max(1, Math.round(p.durationMs));
          const epoch = ctx.safetyEpoch();
          const reply = await sendMotion(ctx, epoch, 'drive', params);
          const data = {
            moveId: reply.move_id,
            leftSps: reply.left_sps ?? leftSps,
            rightSps: reply.right_sps ?? rightSps,
            speedClamped: reply.speed_clamped ?? false,
          };
          if (params.duration_ms === undefined || reply.running === false) {
            return { ...data, running: reply.running ?? false };
          }
          const status = await awaitMotion(ctx, reply, params.duration_ms, epoch);
          return {
            ...data,
            running: false,
            leftSteps: status.move_left_steps,
            rightSteps: status.move_right_steps,
          };
        }),
      ),
    moveTo: (x, y, z, speed) =>
      b.call('moveTo', { x, y, z, speed }, (p) => unlessLinkLost(ctx, () => moveTo(ctx, p))),
    stop: () =>
      b.call('stop', {}, async () => {
        const reply = await ctx.command('stop', {}).catch((error: unknown) => {
          throw isHalError(error) && error.code === 'NOT_CONNECTED'
            ? unacknowledgedStop(ctx, error)
            : error;
        });
        return { stopped: reply.stopped, pose: poseData(ctx) };
      }),
    getPose: () => b.read('getPose', {}, (): Pose => ctx.tracker.pose()),
  };
}
