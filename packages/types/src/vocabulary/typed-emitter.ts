/** Told when a listener throws: the event it was called for and what it threw. */
export type ListenerErrorHandler = (event: string, error: unknown) => void;

/**
 * A small typed event emitter, for browsers and Node alike. A listener that throws does not
 * break the emitter: the other listeners of that event still run, `emit` returns normally (so
 * the code that emitted, a simulation step or a navigation cycle, goes on), and the error goes to
 * `onListenerError` (a package passes one that logs it); without one it is dropped.
 */
export class TypedEmitter<Events extends { [K in keyof Events]: unknown }> {
  readonly #listeners = new Map<keyof Events, Set<(payload: never) => void>>();
  readonly #onListenerError: ListenerErrorHandler | undefined;

  constructor(onListenerError?: ListenerErrorHandler) {
    this.#onListenerError = onListenerError;
  }

  /** Calls `listener` on every `event`; returns the function that unsubscribes it. */
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

  /** Whether anyone listens to `event`. */
  has(event: keyof Events): boolean {
    return (this.#listeners.get(event)?.size ?? 0) > 0;
  }

  /** Calls every listener of `event` with `payload`, in the order they were added. */
  emit<K extends keyof Events>(event: K, payload: Events[K]): void {
    const set = this.#listeners.get(event);
    if (set === undefined) return;
    // A copy: a listener that unsubscribes (itself or another) does not change this round.
    for (const listener of [...set]) {
      try {
        (listener as (payload: Events[K]) => void)(payload);
      } catch (error) {
        this.#report(String(event), error);
      }
    }
  }

  #report(event: string, error: unknown): void {
    try {
      this.#onListenerError?.(event, error);
    } catch {
      // the error handler failing must not break the emitter either
    }
  }
}
