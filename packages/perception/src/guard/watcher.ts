import type { Sight, Sighting } from './sighting.js';

/** Why a {@link Watcher} tripped. */
export type Trip =
  { kind: 'obstacle'; sighting: Sighting } | { kind: 'blind'; sinceMs: number; error?: unknown };

/** What a {@link Watcher} needs. */
export interface WatcherOptions {
  sight: Sight;
  periodMs: number;
  blindLimitMs: number;
  /** Whether a look shows something too near. */
  tooNear: (sighting: Sighting) => boolean;
  /** Called once, at the first trip; it stops the robot. */
  onTrip: (trip: Trip) => void;
}

/**
 * Looks ahead every `periodMs` while a motion runs, one look at a time, and trips (once) when a
 * look shows something too near, or when no look has succeeded for `blindLimitMs` of ticks. The
 * blind time is counted in ticks, not read off the wall clock, so a process that was busy (the
 * fast simulated clock runs a whole motion without yielding) is not taken for a blind camera.
 */
export class Watcher {
  readonly #options: WatcherOptions;
  #timer: ReturnType<typeof setTimeout> | undefined;
  #inFlight = false;
  #blindTicks = 0;
  #running = false;
  #trip: Trip | undefined;
  #lastError: unknown;

  constructor(options: WatcherOptions) {
    this.#options = options;
  }

  /** The trip, once it happened. */
  get trip(): Trip | undefined {
    return this.#trip;
  }

  start(): void {
    if (this.#running) return;
    this.#running = true;
    this.#tick();
  }

  stop(): void {
    this.#running = false;
    if (this.#timer !== undefined) clearTimeout(this.#timer);
    this.#timer = undefined;
  }

  #tick(): void {
    if (!this.#running) return;
    const { periodMs, blindLimitMs } = this.#options;
    if (this.#inFlight) this.#blindTicks += 1;
    if (this.#blindTicks * periodMs >= blindLimitMs) {
      this.#tripped({
        kind: 'blind',
        sinceMs: this.#blindTicks * periodMs,
        ...(this.#lastError === undefined ? {} : { error: this.#lastError }),
      });
      return;
    }
    if (!this.#inFlight) this.#look();
    this.#timer = setTimeout(() => this.#tick(), periodMs);
  }

  #look(): void {
    this.#inFlight = true;
    this.#options.sight.look().then(
      (sighting) => {
        this.#inFlight = false;
        if (!this.#running) return;
        this.#blindTicks = 0;
        if (this.#options.tooNear(sighting)) this.#tripped({ kind: 'obstacle', sighting });
      },
      (error: unknown) => {
        // a failed look counts as not seeing: the next tick tries again
        this.#inFlight = false;
        this.#lastError = error;
        if (!this.#running) return;
        this.#blindTicks += 1;
      },
    );
  }

  #tripped(trip: Trip): void {
    if (this.#trip !== undefined || !this.#running) return;
    this.#trip = trip;
    this.stop();
    this.#options.onTrip(trip);
  }
}
