import type { HalBoundary, RobotPort, SafetyInterface } from '@hal/types';

/**
 * The e-stop: `emergencyStop` is never refused (the boundary sanitises any reason, and before
 * `initialize()` or after `cleanup()` the port still latches); only an accepted reset clears it.
 * `isEmergencyStopped` and `getSafetyStatus` answer from the port's cached state at any time.
 */
export function createSafety(b: HalBoundary, port: RobotPort): SafetyInterface {
  return {
    emergencyStop: (reason) =>
      b.call('emergencyStop', { reason }, async (p) => ({
        ...(await port.emergencyStop(p.reason)),
      })),
    isEmergencyStopped: () => port.isEmergencyStopped(),
    resetEmergencyStop: () =>
      b.call('resetEmergencyStop', {}, async () => ({
        estop: false,
        wasEmergencyStopped: await port.resetEmergencyStop(),
      })),
    getSafetyStatus: () => port.safetyStatus(),
  };
}
