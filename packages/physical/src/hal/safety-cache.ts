import { EstopLatch, isHalError, lastTripError } from '@hal/types';
import type { SafetyStatus } from '@hal/types';
import type { Command, StatusReply } from '../protocol/schemas.js';
import type { SessionState } from '../session.js';

/**
 * The host's view of the robot's safety: the robot's own e-stop latch as its replies report it,
 * the host's latch, the last trip and a lost link.
 */
export class SafetyCache {
  /** The robot's own latch, as its last reply said. */
  #robotEstop = false;
  #robotEstopReason: string | undefined;
  /**
   * The host's latch: set by emergencyStop() before anything is sent, cleared only by an accepted
   * reset. It keeps motion refused even if the stop never reached the robot, or the robot restarted
   * (which clears its own latch); on reconnection the HAL e-stops the robot again.
   */
  readonly #host = new EstopLatch();
  #lastStatus: StatusReply | undefined;
  #linkError: string | undefined;

  /** Whether motion is refused: the robot's latch or the host's is set. */
  isEstopped(): boolean {
    return this.#robotEstop || this.#host.latched;
  }

  /** The reason the host latched, while it is latched. */
  get hostLatch(): string | undefined {
    return this.#host.reason;
  }

  /** Latches on the host, before anything is sent, whatever the link does. */
  latchHost(reason: string): void {
    this.#host.latch(reason);
  }

  /** Keeps the cached state in step with a successful reply. */
  observe(cmd: Command, data: Record<string, unknown>): void {
    switch (cmd) {
      case 'get_status': {
        const status = data as unknown as StatusReply;
        this.#lastStatus = status;
        this.#robotEstop = status.safety.estop;
        this.#robotEstopReason = status.safety.estop ? status.safety.estop_reason : undefined;
        break;
      }
      case 'heartbeat':
        this.#robotEstop = data['estop'] === true;
        if (!this.#robotEstop) this.#robotEstopReason = undefined;
        break;
      case 'estop':
        this.#robotEstop = true;
        this.#robotEstopReason = String(data['estop_reason'] ?? '');
        break;
      case 'reset_estop':
        this.#robotEstop = false;
        this.#robotEstopReason = undefined;
        this.#host.reset();
        break;
    }
  }

  /** A refused request: an EMERGENCY_STOPPED refusal means the robot latched on its own. */
  refused(error: unknown): void {
    if (isHalError(error) && error.code === 'EMERGENCY_STOPPED') {
      // a step-limit trip, another host: cache what the robot says
      this.#robotEstop = true;
      const robotDetails = error.details?.['robotDetails'] as Record<string, unknown> | undefined;
      this.#robotEstopReason = String(robotDetails?.['reason'] ?? 'emergency stop');
    }
  }

  linkChanged(state: SessionState, reason: string): void {
    this.#linkError = state === 'lost' ? `link lost: ${reason}` : undefined;
  }

  status(): SafetyStatus {
    const errors: string[] = [];
    if (this.#linkError !== undefined) errors.push(this.#linkError);
    const trip = this.#lastStatus?.safety.last_trip;
    if (trip !== undefined) errors.push(lastTripError(trip));
    const status: SafetyStatus = {
      emergencyStopped: this.isEstopped(),
      batteryLevel: 100,
      errors,
    };
    const reason = this.#robotEstopReason ?? this.#host.reason;
    if (this.isEstopped() && reason !== undefined) status.emergencyStopReason = reason;
    return status;
  }
}
