/**
 * Where the fleet takes its time from. Every wait the fleet makes (a call's timeout, the
 * leader-follower control loop) goes through one of these, so the same code runs on the wall
 * clock and in simulated time (a world stepped by a test or a demo).
 */
export interface FleetScheduler {
  /** The current time, ms (wall clock or simulated). */
  now(): number;
  /** Calls `fn` once, `ms` milliseconds from now; returns the handle for {@link clearTimeout}. */
  setTimeout(fn: () => void, ms: number): unknown;
  /** Cancels a pending {@link setTimeout}; unknown or fired handles are ignored. */
  clearTimeout(handle: unknown): void;
}

/** The wall clock: `Date.now()` (ms since the Unix epoch) and the runtime's own timers (Node and browsers). */
export const realTimeScheduler: FleetScheduler = Object.freeze({
  now: () => Date.now(),
  setTimeout: (fn: () => void, ms: number): unknown => globalThis.setTimeout(fn, ms),
  clearTimeout: (handle: unknown): void =>
    globalThis.clearTimeout(handle as ReturnType<typeof globalThis.setTimeout>),
});

interface Pending {
  id: number;
  dueMs: number;
  fn: () => void;
}

/**
 * A clock that moves only when told to: `advanceTo(ms)` fires, in time order, every timer due by
 * then. Hook it to a simulated world (`world.events.on('tick', (us) => s.advanceTo(us / 1000))`)
 * and the fleet runs in simulated time.
 */
export class SteppedScheduler implements FleetScheduler {
  #nowMs: number;
  #nextId = 1;
  #pending: Pending[] = [];

  constructor(startMs = 0) {
    this.#nowMs = startMs;
  }

  now(): number {
    return this.#nowMs;
  }

  setTimeout(fn: () => void, ms: number): unknown {
    const id = this.#nextId++;
    const delay = Number.isFinite(ms) && ms > 0 ? ms : 0;
    this.#pending.push({ id, dueMs: this.#nowMs + delay, fn });
    return id;
  }

  clearTimeout(handle: unknown): void {
    this.#pending = this.#pending.filter((p) => p.id !== handle);
  }

  /** How many timers wait to fire. */
  get pendingCount(): number {
    return this.#pending.length;
  }

  /** Moves the clock to `ms` (never backwards), firing each timer due by then, earliest first. */
  advanceTo(ms: number): void {
    if (!Number.isFinite(ms)) return;
    for (;;) {
      let next: Pending | undefined;
      for (const p of this.#pending) {
        if (p.dueMs <= ms && (next === undefined || p.dueMs < next.dueMs)) next = p;
      }
      if (next === undefined) break;
      const fired = next;
      this.#pending = this.#pending.filter((p) => p !== fired);
      this.#nowMs = Math.max(this.#nowMs, fired.dueMs);
      fired.fn();
    }
    this.#nowMs = Math.max(this.#nowMs, ms);
  }

  /** Moves the clock forward by `ms`. */
  advanceBy(ms: number): void {
    this.advanceTo(this.#nowMs + ms);
  }
}
