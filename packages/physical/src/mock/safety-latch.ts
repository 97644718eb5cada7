import { Refusal } from './refusal.js';

/** The last trip, as `get_status` reports it. */
export interface Trip {
  reason: string;
  detail: string;
  uptime_ms: number;
}

/** The robot's e-stop latch and its record of trips (protocol 1.0, section 9). */
export class SafetyLatch {
  #estop = false;
  #reason = '';
  #trips = 0;
  #lastTrip: Trip | null = null;
  #latchedUs = 0;

  /** Whether the emergency stop is latched. */
  get estopped(): boolean {
    return this.#estop;
  }

  /** Robot µs when the latch was last set. */
  get latchedUs(): number {
    return this.#latchedUs;
  }

  /** The reason stored with the latch ('' when not latched). */
  get reason(): string {
    return this.#reason;
  }

  /** Latches the emergency stop at robot time `nowUs`. */
  latch(reason: string, nowUs: number): void {
    this.#estop = true;
    this.#reason = reason;
    this.#latchedUs = nowUs;
  }

  /** Clears the latch; returns whether it was set. */
  reset(): boolean {
    const was = this.#estop;
    this.#estop = false;
    this.#reason = '';
    return was;
  }

  /** Records a trip (an e-stop, a step-limit refusal, a host timeout). */
  trip(reason: string, detail: string, uptimeMs: number): void {
    this.#trips += 1;
    this.#lastTrip = { reason, detail, uptime_ms: uptimeMs };
  }

  /** Refuses a command that moves the wheels while the latch is set. */
  refuseWhileLatched(): void {
    if (this.#estop)
      throw new Refusal('EMERGENCY_STOPPED', 'the emergency stop is latched', {
        reason: this.#reason,
      });
  }

  /** The `safety` fields of `get_status` that the latch knows. */
  report(): { estop: boolean; estop_reason: string; trips: number; last_trip: Trip | null } {
    return {
      estop: this.#estop,
      estop_reason: this.#reason,
      trips: this.#trips,
      last_trip: this.#lastTrip,
    };
  }
}
