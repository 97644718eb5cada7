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

/**
 * Stops the wheels at once, latches the e-stop and records the trip. While already latched it
 * only stops: the first reason and latch time are kept, and no trip is counted (protocol 1.1).
 */
export function emergencyStop(
  state: RobotState,
  reason: string,
  trip: { reason: string; detail: string },
): void {
  state.motion.stop('estop');
  if (state.safety.estopped) return;
  state.safety.latch(reason, state.clock.us());
  state.safety.trip(trip.reason, trip.detail, state.clock.uptimeMs());
}

/** What a `stop` or `estop` reply reports (protocol 1.1): the motion it ended, and when. */
export function stopReport(state: RobotState): {
  move_id: number;
  move_outcome: string;
  move_left_steps: number;
  move_right_steps: number;
  left_steps: number;
  right_steps: number;
  uptime_us: number;
  stopped_us: number;
} {
  const { motion } = state;
  return {
    move_id: motion.moveId,
    move_outcome: motion.outcome,
    move_left_steps: motion.moveSteps.left,
    move_right_steps: motion.moveSteps.right,
    left_steps: motion.position.left,
    right_steps: motion.position.right,
    uptime_us: state.clock.us(),
    stopped_us: motion.restUs,
  };
}
