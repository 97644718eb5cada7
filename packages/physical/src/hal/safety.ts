import type { SafetyInterface, SafetyStatus } from '@hal/types';
import type { HalContext } from './context.js';

/**
 * The e-stop: `emergencyStop` latches on the host before `estop` is sent, so motion is refused
 * whatever the link does, then sends it on the safety lane (never behind a pending request); only
 * an accepted `reset_estop` clears both latches. It is never refused: any reason is sanitized by
 * the boundary, and before `initialize()` or after `cleanup()` it latches the host, and the next
 * `initialize()` sends the `estop` to the robot.
 */
export function createSafety(ctx: HalContext): SafetyInterface {
  const b = ctx.boundary;
  return {
    emergencyStop: (reason) =>
      b.call('emergencyStop', { reason }, async (p) => {
        ctx.safety.latchHost(p.reason); // refuse motion at once, whatever the link does
        const reply = await ctx.safetyCommand('estop', { reason: p.reason });
        if (reply === undefined) return { estop: true, reason: p.reason, delivered: false };
        const data: Record<string, unknown> = {
          estop: reply.estop,
          reason: reply.estop_reason,
          delivered: true,
        };
        // protocol 1.1: the motion it ended, and the robot's clock when the wheels stopped
        if (reply.move_id !== undefined) data['moveId'] = reply.move_id;
        if (reply.move_outcome !== undefined) data['moveOutcome'] = reply.move_outcome;
        if (reply.move_left_steps !== undefined) data['leftSteps'] = reply.move_left_steps;
        if (reply.move_right_steps !== undefined) data['rightSteps'] = reply.move_right_steps;
        if (reply.estop_us !== undefined) data['robotEstopUs'] = reply.estop_us;
        return data;
      }),
    isEmergencyStopped: () => ctx.safety.isEstopped(),
    resetEmergencyStop: () =>
      b.call('resetEmergencyStop', {}, async () => {
        const reply = await ctx.command('reset_estop', {});
        return { estop: false, wasEmergencyStopped: reply.was_estopped };
      }),
    getSafetyStatus: (): SafetyStatus => ctx.safety.status(),
  };
}
