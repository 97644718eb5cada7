import { delay, HalError } from '@hal/types';
import type { MotionDone } from '@hal/types';
import type { MotionReply, ReplyOf, RequestParams, StatusReply } from '../protocol/schemas.js';
import type { SafetyInterrupt } from '../safety-lane.js';
import type { HalContext } from './context.js';

type MotionCommand = 'move_cm' | 'rotate_deg' | 'drive';

/** The error a motion call ends with when a stop or e-stop overtook it. */
function interruptError(interrupt: SafetyInterrupt): HalError {
  const r = interrupt.reply;
  const details = {
    moveId: r.move_id,
    outcome: r.move_outcome,
    leftSteps: r.move_left_steps,
    rightSteps: r.move_right_steps,
  };
  return interrupt.cmd === 'estop'
    ? new HalError('EMERGENCY_STOPPED', 'the motion was cut short by the emergency stop', {
        details,
      })
    : new HalError('INTERRUPTED', 'the motion was stopped by stop()', { details });
}

/**
 * Runs `work` until it settles or a stop or e-stop issued after `epoch` is acknowledged, whichever
 * comes first; then the call ends at once with INTERRUPTED or EMERGENCY_STOPPED. (A stop always
 * ends the motion: the robot stopped it, or refuses it as sent before the stop, or the session
 * never sent it.) What `work` does afterwards is ignored.
 */
async function unlessStopped<T>(
  ctx: HalContext,
  epoch: number,
  work: Promise<T>,
  own: { stopping: boolean } = { stopping: false },
): Promise<T> {
  work.catch(() => undefined);
  const stopped = ctx.interrupted(epoch).then((interrupt) => {
    // the motion's own timeout stop: `work` reports TIMEOUT itself
    if (own.stopping) return new Promise<never>(() => undefined);
    throw interruptError(interrupt);
  });
  return await Promise.race([work, stopped]);
}

/** Sends one motion command; a stop acknowledged meanwhile ends it at once. */
export function sendMotion<C extends MotionCommand>(
  ctx: HalContext,
  epoch: number,
  cmd: C,
  params: RequestParams[C],
): Promise<ReplyOf<C>> {
  return unlessStopped(ctx, epoch, ctx.command(cmd, params));
}

function motionDetails(status: StatusReply): Record<string, unknown> {
  return {
    moveId: status.move_id,
    outcome: status.move_outcome,
    leftSteps: status.move_left_steps,
    rightSteps: status.move_right_steps,
  };
}

/**
 * Waits until the robot reports the motion of `reply` finished, polling `get_status` (the first
 * poll at the planned end), or until a stop issued after `epoch` is acknowledged. Rejects with the code its outcome calls for; times out (and stops
 * the robot) `motionTimeoutMarginMs` after 1.2 x the planned duration.
 */
export async function awaitMotion(
  ctx: HalContext,
  reply: MotionReply,
  plannedMs: number,
  epoch: number,
): Promise<StatusReply> {
  const own = { stopping: false };
  return await unlessStopped(ctx, epoch, pollMotion(ctx, reply, plannedMs, own), own);
}

async function pollMotion(
  ctx: HalContext,
  reply: MotionReply,
  plannedMs: number,
  own: { stopping: boolean },
): Promise<StatusReply> {
  const started = performance.now();
  const deadline = started + ctx.timing.real(plannedMs) * 1.2 + ctx.timing.motionMarginMs();
  const poll = ctx.timing.pollMs();
  let wait = Math.max(2, ctx.timing.real(plannedMs));
  for (;;) {
    await delay(Math.min(wait, Math.max(0, deadline - performance.now())));
    wait = poll;
    const status = await ctx.command('get_status', {});
    if (status.move_id === reply.move_id && status.move_outcome !== 'running') {
      switch (status.move_outcome) {
        case 'done':
          return status;
        case 'estop':
          throw new HalError(
            'EMERGENCY_STOPPED',
            'the motion was cut short by the emergency stop',
            {
              details: motionDetails(status),
            },
          );
        case 'host_timeout':
          throw new HalError(
            'INTERRUPTED',
            'the robot stopped the motion: it heard nothing from the host for longer than its host timeout',
            { details: motionDetails(status) },
          );
        default:
          throw new HalError(
            'INTERRUPTED',
            `the motion was ${status.move_outcome} before it finished`,
            {
              details: motionDetails(status),
            },
          );
      }
    }
    if (status.move_id < reply.move_id) {
      // motion ids only grow while the robot runs: a smaller one means it restarted
      throw new HalError(
        'INTERRUPTED',
        'the robot restarted during the motion; it was not resumed',
        {
          details: motionDetails(status),
        },
      );
    }
    if (status.move_id !== reply.move_id) {
      throw new HalError('INTERRUPTED', 'the motion was replaced by another motion', {
        details: motionDetails(status),
      });
    }
    if (performance.now() >= deadline) {
      own.stopping = true;
      await ctx.safetyCommand('stop', {}).catch(() => undefined);
      throw new HalError(
        'TIMEOUT',
        `the robot did not report motion ${reply.move_id} finished within ${Math.round(deadline - started)} ms (planned ${plannedMs} ms); stopped it`,
        { details: { ...motionDetails(status), plannedMs } },
      );
    }
  }
}

/** Runs a `move_cm` or `rotate_deg` to completion. */
export async function runMotion(
  ctx: HalContext,
  cmd: 'move_cm' | 'rotate_deg',
  params: RequestParams['move_cm'] | RequestParams['rotate_deg'],
): Promise<MotionDone> {
  const epoch = ctx.safetyEpoch();
  const reply: MotionReply =
    cmd === 'move_cm'
      ? await sendMotion(ctx, epoch, 'move_cm', params as RequestParams['move_cm'])
      : await sendMotion(ctx, epoch, 'rotate_deg', params as RequestParams['rotate_deg']);
  const planned = reply.duration_ms ?? 0;
  const status = planned > 0 ? await awaitMotion(ctx, reply, planned, epoch) : undefined;
  return {
    moveId: reply.move_id,
    leftSteps: status?.move_left_steps ?? reply.left_steps ?? 0,
    rightSteps: status?.move_right_steps ?? reply.right_steps ?? 0,
    plannedDurationMs: planned,
  };
}
