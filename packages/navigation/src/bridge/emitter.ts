import { errorMessage } from '../errors.js';
import type { NavigationLogger } from '../errors.js';

/**
 * A small typed event emitter (works in browsers and Node). A listener that throws is logged and
 * does not stop the others, nor the code that emitted.
 */
export class TypedEmitter<Events extends { [K in keyof Events]: unknown }> {
  readonly #listeners = new Map<keyof Events, Set<(payload: never) => void>>();
  readonly #logger: NavigationLogger;

  constructor(logger: NavigationLogger) {
    this.#logger = logger;
  }

  /** Adds a listener; returns a function that removes it. */
  on<K extends keyof Events>(event: K, listener: (payload: Events[K]) => void): () => void {
    let set = this.#listeners.get(event);
    if (set === undefined) {
      set = new Set();
      this.#listeners.set(event, set);
    }
    set.add(listener as (payload: never) => void);
    return () => {
      set.delete(listener as (payload: never) => void);
    };
  }

  emit<K extends keyof Events>(event: K, payload: Events[K]): void {
    const set = this.#listeners.get(event);
    if (set === undefined) return;
    for (const listener of [...set]) {
      try {
        (listener as (payload: Events[K]) => void)(payload);
      } catch (error) {
        this.#logger.error('navigation event listener threw', {
          event: String(event),
          error: errorMessage(error),
        });
      }
    }
  }
}
