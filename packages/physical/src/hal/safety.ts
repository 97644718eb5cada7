import type { SafetyInterface, SafetyStatus } from '@hal/types';
import type { HalContext } from './context.js';

/**
 * The e-stop: `emergencyStop` latches on the host before `estop` is sent, so motion is refused
 * whatever the link does; only an accepted `reset_estop` clears both latches.
 */
export function createSafety(ctx: HalContext): SafetyInterface {
  const b = ctx.boundary;
  return {
    emergencyStop: (reason) =>
      b.call('emergencyStop', { reason }, async (p) => {
        const reason = p.reason ?? 'emergency stop';
        ctx.safety.latchHost(reason); // refuse motion at once, whatever the link does
        const reply = await ctx.command('estop', { reason });
        return { estop: reply.estop, reason: reply.estop_reason };
      }),
    isEmergencyStopped: () => ctx.safety.isEstopped(),
    resetEmergencyStop: () =>
      b.call('resetEmergencyStop', {}, async () => {
        const reply = await ctx.command('reset_estop', {});
        return { wasEmergencyStopped: reply.was_estopped };
      }),
    getSafetyStatus: (): SafetyStatus => ctx.safety.status(),
  };
}
