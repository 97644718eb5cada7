import { HalError, isHalError } from '@hal/types';
import type { DriveDone, EmergencyStopDone, MotionCommand, MotionDone } from '@hal/types';
import type { RequestParams } from '../protocol/schemas.js';
import type { HalContext } from './context.js';
import { unacknowledgedStop, unlessLinkLost } from './lost-link.js';
import { awaitMotion, runMotion, sendMotion } from './run-motion.js';

/*
 * The cube's motion and safety commands over its wire session, as a robot port gives them: each
 * resolves when the robot reports it done (or acknowledged), never on the host's word.
 */

/** One `move_cm` or `rotate_deg`; if it loses the link, one stop, and an error saying how that went. */
export async function wireMotion(ctx: HalContext, command: MotionCommand): Promise<MotionDone> {
  const speed = command.speedStepsPerS === undefined ? {} : { speed: command.speedStepsPerS };
  return await unlessLinkLost(ctx, () =>
    command.kind === 'move'
      ? runMotion(ctx, 'move_cm', { left_cm: command.leftCm, right_cm: command.rightCm, ...speed })
      : runMotion(ctx, 'rotate_deg', { degrees: command.degrees, ...speed }),
  );
}

/** `drive`; waited for to its end when it has a duration. */
export async function wireDrive(
  ctx: HalContext,
  leftSps: number,
  rightSps: number,
  durationMs: number | undefined,
): Promise<DriveDone> {
  return await unlessLinkLost(ctx, async () => {
    const params: RequestParams['drive'] = { left_sps: leftSps, right_sps: rightSps };
    if (durationMs !== undefined) params.duration_ms = durationMs;
    const epoch = ctx.safetyEpoch();
    const reply = await sendMotion(ctx, epoch, 'drive', params);
    const data = {
      moveId: reply.move_id,
      leftSps: reply.left_sps ?? leftSps,
      rightSps: reply.right_sps ?? rightSps,
      speedClamped: reply.speed_clamped ?? false,
    };
    if (durationMs === undefined || reply.running === false) {
      return { ...data, running: reply.running ?? false };
    }
    const status = await awaitMotion(ctx, reply, durationMs, epoch);
    return {
      ...data,
      running: false,
      leftSteps: status.move_left_steps,
      rightSteps: status.move_right_steps,
    };
  });
}

/** `stop`; one the robot does not acknowledge fails NOT_CONNECTED (never claims the stop). */
export async function wireStop(ctx: HalContext): Promise<boolean> {
  const reply = await ctx.command('stop', {}).catch((error: unknown) => {
    throw isHalError(error) && error.code === 'NOT_CONNECTED'
      ? unacknowledgedStop(ctx, error)
      : error;
  });
  return reply.stopped;
}

/**
 * Latches on the host before `estop` is sent, so motion is refused whatever the link does, then
 * sends it on the safety lane (never behind a pending request). With no session (before it opens,
 * after it closed) only the host latches, and the next session's opening sends the `estop`.
 */
export async function wireEmergencyStop(
  ctx: HalContext,
  reason: string,
): Promise<EmergencyStopDone> {
  ctx.safety.latchHost(reason); // refuse motion at once, whatever the link does
  const reply = await ctx.safetyCommand('estop', { reason });
  if (reply === undefined) return { estop: true, reason, delivered: false };
  const done: EmergencyStopDone = {
    estop: reply.estop,
    reason: reply.estop_reason,
    delivered: true,
  };
  // protocol 1.1: the motion it ended, and the robot's clock when the wheels stopped
  if (reply.move_id !== undefined) done.moveId = reply.move_id;
  if (reply.move_outcome !== undefined) done.moveOutcome = reply.move_outcome;
  if (reply.move_left_steps !== undefined) done.leftSteps = reply.move_left_steps;
  if (reply.move_right_steps !== undefined) done.rightSteps = reply.move_right_steps;
  if (reply.estop_us !== undefined) done.robotEstopUs = reply.estop_us;
  return done;
}

/** `reset_estop`: only an accepted one clears the host's latch and the robot's. */
export async function wireResetEmergencyStop(ctx: HalContext): Promise<boolean> {
  return (await ctx.command('reset_estop', {})).was_estopped;
}

/** The error of a command sent with no session open (before `open()`, after `close()`). */
export const notInitialised = (): HalError =>
  new HalError('NOT_READY', 'the HAL is not initialised');
