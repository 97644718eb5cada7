import type { z } from 'zod';
import { inspect } from './inspect.js';
import type { Inspected } from './inspect.js';
import type { DeviceWire } from './wire.js';

/** One streamed message and when it arrived (performance.now() ms). */
export interface Received<T> {
  atMs: number;
  inspected: Inspected<T>;
}

const KEEP = 20_000;

/** What rate and format checks read of a stream, whatever its payload. */
export interface StreamView {
  readonly messages: readonly Received<unknown>[];
  readonly startedAtMs: number;
  since(atMs: number): Received<unknown>[];
}

/** Collects a stream of the device (state, IMU, range, announcements) and waits on it. */
export class StreamCollector<T> implements StreamView {
  readonly messages: Received<T>[] = [];
  readonly startedAtMs = performance.now();
  readonly #waiters = new Set<(r: Received<T>) => void>();

  constructor(
    wire: DeviceWire,
    readonly subject: string,
    schema: z.ZodType<T>,
    deviceId: string,
  ) {
    wire.subscribe(subject, (data, atMs) => {
      const received = { atMs, inspected: inspect(data, schema, deviceId) };
      this.messages.push(received);
      if (this.messages.length > KEEP) this.messages.splice(0, this.messages.length - KEEP);
      for (const waiter of [...this.#waiters]) waiter(received);
    });
  }

  /** Messages that arrived at or after `atMs`. */
  since(atMs: number): Received<T>[] {
    return this.messages.filter((m) => m.atMs >= atMs);
  }

  /** The newest valid payload, if any. */
  latest(): T | undefined {
    for (let i = this.messages.length - 1; i >= 0; i -= 1) {
      const payload = this.messages[i]?.inspected.payload;
      if (payload !== undefined) return payload;
    }
    return undefined;
  }

  /**
   * The first valid payload arriving from now on that `match` accepts (default: any), or
   * undefined after `timeoutMs`.
   */
  next(timeoutMs: number, match: (payload: T) => boolean = () => true): Promise<T | undefined> {
    return new Promise((resolve) => {
      const waiter = (r: Received<T>) => {
        const payload = r.inspected.payload;
        if (payload === undefined || !match(payload)) return;
        done(payload);
      };
      const done = (payload: T | undefined) => {
        clearTimeout(timer);
        this.#waiters.delete(waiter);
        resolve(payload);
      };
      const timer = setTimeout(() => done(undefined), timeoutMs);
      this.#waiters.add(waiter);
    });
  }
}
