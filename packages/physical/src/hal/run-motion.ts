import { HalError } from '@hal/types';
import type { MotionReply, RequestParams, StatusReply } from '../protocol/schemas.js';
import type { HalContext } from './context.js';

const sleep = (ms: number) => new Promise<void>((resolve) => setTimeout(resolve, ms));

/** The pose as result data: metres and radians. */
export function poseData(ctx: HalContext): Record<string, number> {
  const pose = ctx.tracker.pose();
  return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
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
 * poll at the planned end). Rejects with the code its outcome calls for; times out (and stops
 * the robot) `motionTimeoutMarginMs` after 1.2 x the planned duration.
 */
export async function awaitMotion(
  ctx: HalContext,
  reply: MotionReply,
  plannedMs: number,
): Promise<StatusReply> {
  const started = performance.now();
  const deadline = started + ctx.timing.real(plannedMs) * 1.2 + ctx.timing.motionMarginMs();
  const poll = ctx.timing.pollMs();
  let wait = Math.max(2, ctx.timing.real(plannedMs));
  for (;;) {
    await sleep(Math.min(wait, Math.max(0, deadline - performance.now())));
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
      await ctx.command('stop', {}).catch(() => undefined);
      throw new HalError(
        'TIMEOUT',
        `the robot did not report motion ${reply.move_id} finished within ${Math.round(deadline - started)} ms (planned ${plannedMs} ms); stopped it`,
        { details: { ...motionDetails(status), plannedMs } },
      );
    }
  }
}

/** Runs a `move_cm` or `rotate_deg` to completion; returns the result data. */
export async function runMotion(
  ctx: HalContext,
  cmd: 'move_cm' | 'rotate_deg',
  params: RequestParams['move_cm'] | RequestParams['rotate_deg'],
): Promise<Record<string, unknown>> {
  const reply: MotionReply =
    cmd === 'move_cm'
      ? await ctx.command('move_cm', params as RequestParams['move_cm'])
      : await ctx.command('rotate_deg', params as RequestParams['rotate_deg']);
  const planned = reply.duration_ms ?? 0;
  const status = planned > 0 ? await awaitMotion(ctx, reply, planned) : undefined;
  return {
    moveId: reply.move_id,
    leftSteps: status?.move_left_steps ?? reply.left_steps ?? 0,
    rightSteps: status?.move_right_steps ?? reply.right_steps ?? 0,
    plannedDurationMs: planned,
    pose: poseData(ctx),
  };
}
