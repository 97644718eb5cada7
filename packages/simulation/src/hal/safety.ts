import type { SafetyInterface, SafetyStatus } from '@hal/types';
import type { HalContext } from './context.js';

/**
 * The simulated robot's safety: the firmware's `estop` and `reset_estop`, and its status (the
 * latch, its reason, the last trip). Every change emits a `safety` event.
 */
export function createSafety(ctx: HalContext): SafetyInterface {
  const b = ctx.boundary;
  const status = (): SafetyStatus => {
    const r = ctx.robot();
    const errors: string[] = [];
    if (r.lastTrip !== undefined) {
      errors.push(`${r.lastTrip.reason}: ${r.lastTrip.detail}`);
    }
    const s: SafetyStatus = {
      emergencyStopped: r.emergencyStopped,
      batteryLevel: 100,
      errors,
    };
    if (r.emergencyStopped) s.emergencyStopReason = r.emergencyStopReason;
    return s;
  };
  return {
    emergencyStop: (reason) =>
      b.call('emergencyStop', { reason }, async (p) => {
        // never refused: the boundary sanitized the reason, and before initialize() or after
        // cleanup() the simulated robot still latches
        ctx.robot().emergencyStop(p.reason);
        ctx.events.emit('safety', status());
        return { estop: true, reason: ctx.robot().emergencyStopReason };
      }),
    isEmergencyStopped: () => ctx.robot().emergencyStopped,
    resetEmergencyStop: () =>
      b.call('resetEmergencyStop', {}, async () => {
        const was = ctx.robot().resetEmergencyStop();
        ctx.events.emit('safety', status());
        return { estop: false, wasEmergencyStopped: was };
      }),
    getSafetyStatus: status,
  };
}
