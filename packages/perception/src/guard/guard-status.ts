import type { GuardSource } from './sighting.js';

/** A motion the guard refused or stopped for an obstacle ahead. */
export interface GuardStop {
  /** The call: moveForward, moveTo, drive. */
  motion: string;
  /** The free distance seen ahead of the body's front, metres. */
  distanceM: number;
  source: GuardSource;
  /** Whether what was seen reached the edge of the view (it is at `distanceM` or nearer). */
  atEdge: boolean;
  /** 'before': refused, nothing moved; 'during': stopped on the way. */
  when: 'before' | 'during';
  /** How far the robot went in this call before it stopped, metres (odometry). */
  travelledM: number;
  /** When, ms since the epoch. */
  at: number;
}

/** What the guard has done, for a run's result and recording. */
export interface GuardStatus {
  /** What it watches with; 'nothing' when the robot has neither; 'unknown' before it looked. */
  sees: GuardSource | 'nothing' | 'unknown';
  standoffM: number;
  /** Motions answered OBSTACLE_AHEAD (refused or stopped). */
  stops: number;
  /** Of those, refused before anything moved. */
  refused: number;
  /** Motions stopped (or refused) because the guard could not see: its sense failed or was late. */
  blindStops: number;
  /** Motions that went through unwatched: reverses, and all of them when it cannot see. */
  unguarded: number;
  lastStop?: GuardStop;
  /** Why it cannot guard (no camera, no range sensors), said once. */
  warning?: string;
}

/** What the guard reports as it happens. */
export type GuardEvent =
  | { type: 'obstacle'; stop: GuardStop }
  | { type: 'blind'; motion: string; message: string; at: number }
  | { type: 'unguarded'; motion: string; message: string; at: number }
  | { type: 'cannot-guard'; message: string; at: number };

/** A listener of {@link GuardEvent}s. */
export type GuardListener = (event: GuardEvent) => void;

/** The guard's record: counts, the last stop, listeners. */
export class GuardRecord {
  readonly #status: GuardStatus;
  readonly #listeners = new Set<GuardListener>();

  constructor(standoffM: number) {
    this.#status = {
      sees: 'unknown',
      standoffM,
      stops: 0,
      refused: 0,
      blindStops: 0,
      unguarded: 0,
    };
  }

  /** A copy of the status now. */
  status(): GuardStatus {
    const copy: GuardStatus = { ...this.#status };
    if (this.#status.lastStop !== undefined) copy.lastStop = { ...this.#status.lastStop };
    return copy;
  }

  set sees(sees: GuardStatus['sees']) {
    this.#status.sees = sees;
  }

  on(listener: GuardListener): () => void {
    this.#listeners.add(listener);
    return () => this.#listeners.delete(listener);
  }

  obstacle(stop: GuardStop): void {
    this.#status.stops += 1;
    if (stop.when === 'before') this.#status.refused += 1;
    this.#status.lastStop = stop;
    this.#emit({ type: 'obstacle', stop });
  }

  blind(motion: string, message: string): void {
    this.#status.blindStops += 1;
    this.#emit({ type: 'blind', motion, message, at: Date.now() });
  }

  unguarded(motion: string, message: string): void {
    this.#status.unguarded += 1;
    this.#emit({ type: 'unguarded', motion, message, at: Date.now() });
  }

  cannotGuard(message: string): void {
    this.#status.warning = message;
    this.#emit({ type: 'cannot-guard', message, at: Date.now() });
  }

  #emit(event: GuardEvent): void {
    for (const listener of this.#listeners) {
      try {
        listener(event);
      } catch {
        // a listener that throws must not break the guard
      }
    }
  }
}
