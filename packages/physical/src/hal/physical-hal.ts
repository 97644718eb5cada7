import { RobotHAL } from '@hal/runtime';
import type { HALConfig, RobotConfig } from '@hal/types';
import type { ReportedSteps } from '../pose-tracker.js';
import type { StatusReply } from '../protocol/schemas.js';
import type { SessionState } from '../session.js';
import type { SerialLinkStats, TransportStats } from '../transport/transport.js';
import type { WheelCalibration } from './calibration.js';
import type { PhysicalHALOptions, RobotIdentity } from './options.js';
import { WireBinding } from './wire-binding.js';

/**
 * The HAL of the physical V1 stepper cube: the one {@link RobotHAL} over the cube's wire session
 * ({@link WireBinding}), protocol 1.1 (docs/protocol.md) over UDP or serial. Every public call goes
 * through the shared boundary; a motion resolves when the robot reports it finished; the pose is
 * dead-reckoned on the host from the robot's step counters, in a frame anchored where the robot
 * stood at `initialize()` (the origin, or `startPose`).
 */
export class PhysicalHAL extends RobotHAL<WireBinding> {
  declare readonly mode: 'physical';

  constructor(config: HALConfig, options: PhysicalHALOptions = {}) {
    super(new WireBinding(config, options));
  }

  /** What the robot reported in `hello` (undefined before `initialize()`). */
  get identity(): RobotIdentity | undefined {
    return this.binding.identity;
  }

  /** The link's round-trip statistics. */
  transportStats(): TransportStats | undefined {
    return this.binding.transportStats();
  }

  /**
   * The wheel step counters and speeds the robot last reported (its status and stop replies, not
   * the host's prediction between them); undefined before `initialize()` has read a status.
   */
  reportedSteps(): ReportedSteps | undefined {
    return this.binding.reportedSteps();
  }

  /** The serial link's frame statistics (undefined on other links). */
  linkStats(): SerialLinkStats | undefined {
    return this.binding.linkStats();
  }

  /** The link state: `connected`, `lost` (reconnecting), `closed`, or `idle` before initialize. */
  get linkState(): SessionState {
    return this.binding.linkState;
  }

  /** Stops sending heartbeats, so the robot's host timeout can be seen to fire (for tests). */
  pauseHeartbeat(): void {
    this.binding.pauseHeartbeat();
  }

  /** Sends heartbeats again. */
  resumeHeartbeat(): void {
    this.binding.resumeHeartbeat();
  }

  /**
   * Sends `calibration` to the robot now (`set_config`), uses it for the host's odometry and
   * validation, and sends it again after every later hello of this HAL (reconnects). Resolves the
   * robot configuration now in use; RANGE_EXCEEDED naming the field when a value is outside the
   * firmware's range (nothing is sent), the robot's own code when it refuses.
   */
  async applyCalibration(calibration: WheelCalibration): Promise<RobotConfig> {
    return await this.binding.applyCalibration(calibration);
  }

  /** Asks the robot for its status now (and updates the pose and safety state from it). */
  async refreshStatus(): Promise<StatusReply> {
    return await this.binding.refreshStatus();
  }
}
