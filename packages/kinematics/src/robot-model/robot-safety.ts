import { HalError } from '@hal/types';

/** A safety trip, as the firmware records it. */
export interface SafetyTrip {
  reason: 'estop_command' | 'step_limit' | 'host_timeout';
  detail: string;
  /** Robot time, µs. */
  atUs: number;
}

/** What the safety layer needs from its robot. */
export interface RobotSafetyHooks {
  /** The robot's time, µs. */
  nowUs(): number;
  /** Ends the running motion at once with this outcome (nothing when none runs). */
  stopMotion(outcome: 'estop' | 'host_timeout'): void;
}

/**
 * The robot's safety, as the firmware keeps it (cube.cpp, cube_motion_commands.cpp): the latched
 * emergency stop, the per-command step limit (a trip latches the e-stop), the host link and its
 * timeout (a trip stops the motion and latches nothing), and the record of trips. Messages and
 * reasons are the firmware's, word for word.
 */
export class RobotSafety {
  readonly #hooks: RobotSafetyHooks;
  #latched = false;
  #reason = '';
  #latchedUs = 0;
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
  /** The reason stored with the latch ('' when not latched). */
  get emergencyStopReason(): string {
    return this.#reason;
  }
  /** Robot time the latch was last set, µs (0: never). */
  get latchedUs(): number {
    return this.#latchedUs;
  }
  get trips(): number {
    return this.#trips;
  }
  get lastTrip(): SafetyTrip | undefined {
    return this.#lastTrip;
  }
  /** Whether the host is silent: no heartbeats between its requests. */
  get hostSilent(): boolean {
    return this.#hostSilent;
  }
  /** Robot time the host was last heard, µs. */
  get lastHostUs(): number {
    return this.#lastHostUs;
  }

  // ---- emergency stop ----------------------------------------------------------------------

  /**
   * `estop`: stops at once and latches until {@link reset}. While already latched it only stops:
   * the first reason and time are kept and no trip is counted (protocol 1.1: a resent stop is
   * harmless).
   */
  emergencyStop(reason: string): void {
    this.#latch('estop_command', reason);
  }

  /** `reset_estop`: clears the latch. Returns whether it was latched. */
  reset(): boolean {
    const was = this.#latched;
    this.#latched = false;
    this.#reason = '';
    return was;
  }

  /** Throws EMERGENCY_STOPPED while the e-stop is latched (every motion command checks first). */
  refuseWhileLatched(): void {
    if (this.#latched) {
      throw new HalError(
        'EMERGENCY_STOPPED',
        `emergency stop is latched (${this.#reason}); send reset_estop first`,
        { details: { reason: this.#reason } },
      );
    }
  }

  // ---- step limit --------------------------------------------------------------------------

  /**
   * More than `limit` steps on a wheel in one command (`field` names the request field it came
   * from): latches the e-stop and throws RANGE_EXCEEDED.
   */
  checkStepLimit(field: string, steps: number, limit: number): void {
    if (Math.abs(steps) <= limit) return;
    this.#latch('step_limit', `step limit: "${field}" ${steps} steps`);
    throw new HalError(
      'RANGE_EXCEEDED',
      `"${field}" gives ${steps} steps; the limit is ${limit} steps per command (emergency stop latched)`,
      { details: { field, min: -limit, max: limit, value: steps, estop: true } },
    );
  }

  // ---- host link ---------------------------------------------------------------------------

  /** A valid request from the host arrived now (every command counts; so do heartbeats). */
  touchHost(): void {
    this.#lastHostUs = this.#hooks.nowUs();
  }

  /**
   * The host falls silent (true: no heartbeats, only its requests are heard) or speaks again
   * (false: it is heard throughout, as a host that sends its heartbeats).
   */
  setHostSilent(silent: boolean): void {
    if (silent && !this.#hostSilent) this.#lastHostUs = this.#hooks.nowUs();
    this.#hostSilent = silent;
  }

  /**
   * Time passes to `nowUs`: a talking host is heard throughout (its heartbeats); for a silent
   * one, returns when its timeout of `timeoutMs` expires if that is by `nowUs`.
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
    this.#record('host_timeout', `no request from the host for ${timeoutMs} ms`);
    this.#hooks.stopMotion('host_timeout');
  }

  // ---- internals ---------------------------------------------------------------------------

  #latch(reason: 'estop_command' | 'step_limit', detail: string): void {
    this.#hooks.stopMotion('estop');
    if (this.#latched) return;
    this.#latched = true;
    this.#reason = detail;
    this.#latchedUs = this.#hooks.nowUs();
    this.#record(reason, detail);
  }

  #record(reason: SafetyTrip['reason'], detail: string): void {
    this.#trips += 1;
    this.#lastTrip = { reason, detail, atUs: this.#hooks.nowUs() };
  }
}
