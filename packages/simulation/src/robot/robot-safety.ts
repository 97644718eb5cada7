import { HalError } from '@hal/types';

/** A safety trip, as the firmware records it. */
export interface SafetyTrip {
  reason: 'estop_command' | 'step_limit' | 'host_timeout';
  detail: string;
  /** Simulated time, µs. */
  atUs: number;
}

/** What the safety layer needs from its robot. */
export interface RobotSafetyHooks {
  /** The robot's simulated time, µs. */
  nowUs(): number;
  /** Ends the running motion at once with this outcome (nothing when none runs). */
  stopMotion(outcome: 'estop' | 'host_timeout'): void;
}

/**
 * The robot's safety, as the firmware keeps it: the latched emergency stop, the per-command step
 * limit (a trip latches the e-stop), the host link and its timeout (a trip stops the motion and
 * latches nothing), and the record of trips.
 */
export class RobotSafety {
  readonly #hooks: RobotSafetyHooks;
  #latched = false;
  #reason = '';
  #trips = 0;
  #lastTrip: SafetyTrip | undefined;
  #hostSilent = false;
  #lastHostUs = 0;

  constructor(hooks: RobotSafetyHooks) {
    this.#hooks = hooks;
  }

  get emergencyStopped(): boolean {
    return this.#latched;
  }
  get emergencyStopReason(): string {
    return this.#reason;
  }
  get trips(): number {
    return this.#trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#lastTrip;
  }
  /** Whether the host is (simulated as) silent: no heartbeats between commands. */
  get hostSilent(): boolean {
    return this.#hostSilent;
  }

  // ---- emergency stop ----------------------------------------------------------------------

  /**
   * `estop`: stops at once and latches until {@link reset}. While already latched it only stops:
   * the first reason is kept and no trip is counted (protocol 1.1: a resent stop is harmless).
   */
  emergencyStop(reason: string): void {
    if (this.#latched) {
      this.#hooks.stopMotion('estop');
      return;
    }
    this.#trip('estop_command', reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  reset(): boolean {
    const was = this.#latched;
    this.#latched = false;
    this.#reason = '';
    return was;
  }

  /** Throws EMERGENCY_STOPPED while the e-stop is latched (every motion command checks). */
  refuseWhileLatched(): void {
    if (this.#latched) {
      throw new HalError('EMERGENCY_STOPPED', `the emergency stop is latched (${this.#reason})`, {
        details: { reason: this.#reason },
      });
    }
  }

  // ---- step limit --------------------------------------------------------------------------

  /** More than `limit` steps on a wheel in one command: trips the e-stop, throws RANGE_EXCEEDED. */
  checkStepLimit(left: number, right: number, limit: number): void {
    const worst = Math.abs(left) >= Math.abs(right) ? left : right;
    if (Math.abs(worst) > limit) {
      const field = worst === left ? 'left' : 'right';
      this.#trip('step_limit', `"${field}" ${worst} steps is over the ${limit} step limit`);
      throw new HalError(
        'RANGE_EXCEEDED',
        `"${field}" must be -${limit}..${limit} steps, got ${worst}; the emergency stop has tripped`,
        { details: { field, min: -limit, max: limit, value: worst, estop: true } },
      );
    }
  }

  // ---- host link ---------------------------------------------------------------------------

  /** A valid request from the host arrived now (every command counts; so do heartbeats). */
  touchHost(): void {
    this.#lastHostUs = this.#hooks.nowUs();
  }

  /** The host falls silent (true: no heartbeats) or speaks again (false). */
  setHostSilent(silent: boolean): void {
    if (silent && !this.#hostSilent) this.#lastHostUs = this.#hooks.nowUs();
    this.#hostSilent = silent;
  }

  /**
   * Simulated time passes to `nowUs`: a talking host is heard throughout (its heartbeats); for a
   * silent one, returns when its timeout of `timeoutMs` expires if that is by `nowUs`.
   */
  hostTimeoutBy(nowUs: number, timeoutMs: number): number | undefined {
    if (!this.#hostSilent) {
      this.#lastHostUs = nowUs;
      return undefined;
    }
    const deadline = this.#lastHostUs + timeoutMs * 1000;
    return deadline <= nowUs ? deadline : undefined;
  }

  /** When a silent host's timeout of `timeoutMs` expires, µs; Infinity while the host talks. */
  silentDeadlineUs(timeoutMs: number): number {
    return this.#hostSilent ? this.#lastHostUs + timeoutMs * 1000 : Number.POSITIVE_INFINITY;
  }

  /** The host timeout expired: records the trip and stops the motion (nothing latches). */
  hostTimedOut(timeoutMs: number): void {
    this.#trip('host_timeout', `no request from the host for ${timeoutMs} ms`);
  }

  // ---- internals ---------------------------------------------------------------------------

  #trip(reason: SafetyTrip['reason'], detail: string): void {
    this.#trips += 1;
    this.#lastTrip = { reason, detail, atUs: this.#hooks.nowUs() };
    if (reason === 'host_timeout') {
      this.#hooks.stopMotion('host_timeout');
      return;
    }
    this.#hooks.stopMotion('estop');
    this.#latched = true;
    this.#reason = reason === 'step_limit' ? 'step_limit' : detail;
  }
}
