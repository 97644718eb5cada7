import { nextTurn } from '@hal/types';
import type { HardwareAbstractionLayer, ScopedLogger } from '@hal/types';

export interface ControllerWatchOptions {
  /** A watched client that has sent nothing for longer than this, ms, has gone silent. */
  timeoutMs: number;
  /** Where a stop on a client's behalf is said, and a stop that failed. */
  log: ScopedLogger;
  /**
   * What happens when a watched client goes silent (once: it is no longer watched after).
   * Default: the robot is stopped on its behalf ({@link ControllerWatch.stopFor}).
   */
  onSilent?: (client: string, silentMs: number) => void;
  /** The clock, ms. Default `Date.now`. */
  now?: () => number;
}

/**
 * The server side of "a controller that vanishes has its motion stopped within the heartbeat
 * timeout", for every server of a HAL (WebSocket, NATS). The server watches the clients whose
 * silence must stop the robot, tells the watch whenever one of them is heard (a call or a
 * heartbeat), and a client silent for longer than `timeoutMs` gets `onSilent` once: by default
 * the robot is stopped, and the log says for whom and why.
 */
export class ControllerWatch {
  readonly #hal: HardwareAbstractionLayer;
  readonly #options: ControllerWatchOptions;
  readonly #now: () => number;
  /** The watched clients and when each was last heard, ms. */
  readonly #lastHeard = new Map<string, number>();
  readonly #timer: ReturnType<typeof setInterval>;
  #checking = false;

  constructor(hal: HardwareAbstractionLayer, options: ControllerWatchOptions) {
    this.#hal = hal;
    this.#options = options;
    this.#now = options.now ?? Date.now;
    const every = Math.max(10, Math.min(250, options.timeoutMs / 5));
    this.#timer = setInterval(() => this.#checkAfterInput(), every);
    (this.#timer as { unref?: () => void }).unref?.();
  }

  /** Starts watching `client` (heard now). */
  watch(client: string): void {
    this.#lastHeard.set(client, this.#now());
  }

  /** `client` sent something: its silence starts again. Clients not watched are ignored. */
  heard(client: string): void {
    if (this.#lastHeard.has(client)) this.#lastHeard.set(client, this.#now());
  }

  /** Stops watching `client`, or every client when none is named. */
  forget(client?: string): void {
    if (client === undefined) this.#lastHeard.clear();
    else this.#lastHeard.delete(client);
  }

  /** Whether `client` is watched. */
  watches(client: string): boolean {
    return this.#lastHeard.has(client);
  }

  /**
   * Stops the robot on behalf of `client`, which `why` (is gone, went silent), and says so; a
   * stop that fails is logged as an error. Never rejects.
   */
  async stopFor(client: string, why: string): Promise<void> {
    this.#options.log.warn(`controller ${client} ${why}: stopping the robot`, { client });
    try {
      const result = await this.#hal.locomotion.stop();
      if (!result.success) {
        this.#options.log.error(`the stop for controller ${client} failed`, {
          client,
          code: result.code,
          error: result.error,
        });
      }
    } catch (error) {
      this.#options.log.error(`the stop for controller ${client} failed`, {
        client,
        error: String(error),
      });
    }
  }

  /** Gives every client silent for longer than the timeout its `onSilent`, once (run by a timer). */
  check(): void {
    const now = this.#now();
    for (const [client, heard] of [...this.#lastHeard]) {
      const silentMs = now - heard;
      if (silentMs <= this.#options.timeoutMs) continue;
      this.#lastHeard.delete(client);
      if (this.#options.onSilent !== undefined) this.#options.onSilent(client, silentMs);
      else void this.stopFor(client, `silent for ${silentMs} ms`);
    }
  }

  /**
   * The timer's check. A client can look silent only because this process was held up (a long
   * task, a starved CPU) with its messages waiting unread, and timers run before input is read:
   * so a client that looks silent gets its verdict a turn later, once what was waiting is read.
   */
  #checkAfterInput(): void {
    if (this.#checking) return;
    const now = this.#now();
    const timeout = this.#options.timeoutMs;
    if (![...this.#lastHeard.values()].some((heard) => now - heard > timeout)) return;
    this.#checking = true;
    nextTurn(() => {
      this.#checking = false;
      this.check();
    });
  }

  close(): void {
    clearInterval(this.#timer);
    this.#lastHeard.clear();
  }
}
