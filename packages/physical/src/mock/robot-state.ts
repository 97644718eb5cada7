import type { DeviceSettings } from '../protocol/device-config.js';
import type { LedState } from '../protocol/schemas.js';
import type { MotionState } from './motion-state.js';
import type { RobotClock } from './robot-clock.js';
import type { SafetyLatch } from './safety-latch.js';

/** Everything the mock robot's command handlers read and change. */
export interface RobotState {
  readonly clock: RobotClock;
  readonly motion: MotionState;
  readonly safety: SafetyLatch;
  /** The current configuration (`set_config` replaces it). */
  settings: DeviceSettings;
  led: LedState;
}

/** Stops the wheels at once, latches the e-stop and records the trip. */
export function emergencyStop(
  state: RobotState,
  reason: string,
  trip: { reason: string; detail: string },
): void {
  state.motion.stop('estop');
  state.safety.latch(reason);
  state.safety.trip(trip.reason, trip.detail, state.clock.uptimeMs());
}
