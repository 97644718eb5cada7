import type { SafetyInterface, SafetyStatus } from '@hal/types';
import type { HybridContext } from './context.js';

/**
 * The e-stop of both robots. `emergencyStop` latches the hybrid HAL before either robot is asked,
 * so motion is refused whatever happens on the way; it is stopped while either robot, or the
 * hybrid's own latch, is stopped. Only a reset the physical robot accepts clears the hybrid latch.
 */
export function createSafety(ctx: HybridContext): SafetyInterface {
  const { physical: p, twin: t } = ctx;
  let latchReason: string | undefined;
  const isEmergencyStopped = (): boolean =>
    latchReason !== undefined || p.safety.isEmergencyStopped() || t.safety.isEmergencyStopped();

  return {
    emergencyStop: (reason) =>
      ctx.run(
        'emergencyStop',
        { reason },
        (a) => {
          latchReason = a.reason; // sanitized by the boundary: never refused
          return p.safety.emergencyStop(a.reason);
        },
        (a) => t.safety.emergencyStop(a.reason),
      ),
    isEmergencyStopped,
    resetEmergencyStop: async () => {
      const result = await ctx.run(
        'resetEmergencyStop',
        {},
        () => p.safety.resetEmergencyStop(),
        () => t.safety.resetEmergencyStop(),
      );
      if (result.success) latchReason = undefined;
      return result;
    },
    getSafetyStatus: (): SafetyStatus =>
      mergeSafetyStatus(
        p.safety.getSafetyStatus(),
        t.safety.getSafetyStatus(),
        isEmergencyStopped(),
        latchReason,
      ),
  };
}

/**
 * One safety status from both: the physical robot's battery and temperature, the errors of both
 * (the twin's prefixed `twin: `), and the first reason a stop was latched.
 */
export function mergeSafetyStatus(
  physical: SafetyStatus,
  twin: SafetyStatus,
  emergencyStopped: boolean,
  latchReason?: string,
): SafetyStatus {
  const status: SafetyStatus = {
    emergencyStopped,
    batteryLevel: physical.batteryLevel,
    errors: [...physical.errors, ...twin.errors.map((error) => `twin: ${error}`)],
  };
  if (physical.temperature !== undefined) status.temperature = physical.temperature;
  const reason =
    physical.emergencyStopReason ??
    latchReason ??
    (twin.emergencyStopReason === undefined ? undefined : `twin: ${twin.emergencyStopReason}`);
  if (emergencyStopped && reason !== undefined) status.emergencyStopReason = reason;
  return status;
}
