import { nextTurn } from '@hal/types';

/** How a recorder's background work is scheduled. */
export interface BackgroundWorkOptions {
  /** Does one piece of work; resolves false when there was none left. */
  step: () => boolean | Promise<boolean>;
  /** Whether work is waiting. */
  hasWork: () => boolean;
  /**
   * The longest work waits for a moment with no call on its way (ms). Past it, while calls keep
   * coming back to back, work runs in every turn until a moment with none on its way.
   */
  maxHoldMs: number;
  /** The longest one turn of work runs before it yields to the event loop (ms). */
  sliceMs: number;
  /** How often waiting work looks for a moment with no call on its way (ms). */
  tickMs: number;
}

/** Ticks with no work before the ticker stops (it starts again with the next work). */
const IDLE_TICKS_BEFORE_STOP = 100;

/**
 * Runs a recorder's work (making records, encoding them, writing chunks) in the moments no
 * recorded call is on its way to the robot. A reply that comes in while the main thread encodes
 * or compresses waits for it; a call made while no work runs is answered as fast as unrecorded.
 *
 * A call's path schedules nothing: queued work waits for a ticker (every `tickMs`) that finds no
 * call on its way, and then runs, a slice of at most `sliceMs` at a time, until a call starts or
 * nothing is left. (On a CPU woken from idle, arming an immediate from the call's path took
 * about 15 µs, as much as the rest of the call's recording path.) A robot's loop that pauses
 * between its calls (a control loop, an agent) never meets the recording's work; one that
 * sends back to back for longer than `maxHoldMs` meets it between its calls.
 */
export class BackgroundWork {
  readonly #options: BackgroundWorkOptions;
  #inFlight = 0;
  #running: Promise<void> | undefined;
  #ticker: ReturnType<typeof setInterval> | undefined;
  #idleTicks = 0;
  /** When a tick first found work held back by a call on its way (reset by one finding none). */
  #heldSince: number | undefined;
  /** Work has waited `maxHoldMs`: it runs every turn until a tick finds no call on its way. */
  #catchingUp = false;
  #flushing = 0;

  constructor(options: BackgroundWorkOptions) {
    this.#options = options;
  }

  /** Marks a call on its way; returns the function that marks it answered (once). */
  callStarted(): () => void {
    this.#inFlight += 1;
    let ended = false;
    return () => {
      if (ended) return;
      ended = true;
      this.#inFlight -= 1;
    };
  }

  /** There is work: it runs at the next moment with no call on its way. */
  kick(): void {
    // never in this turn: the kick comes from a call's path
    if (this.#catchingUp || this.#flushing > 0) this.#start(false);
    else if (this.#ticker === undefined) {
      this.#idleTicks = 0;
      this.#ticker = setInterval(() => this.#tick(), this.#options.tickMs);
      (this.#ticker as { unref?: () => void }).unref?.();
    }
  }

  /** Runs every piece of work there is, calls on their way or not; resolves when none is left. */
  async flush(): Promise<void> {
    this.#flushing += 1;
    try {
      while (this.#running !== undefined || this.#options.hasWork()) {
        this.#start(true);
        await this.#running;
      }
    } finally {
      this.#flushing -= 1;
    }
  }

  /** Stops the ticker (work already queued still runs with {@link flush}). */
  stop(): void {
    if (this.#ticker !== undefined) clearInterval(this.#ticker);
    this.#ticker = undefined;
  }

  #tick(): void {
    const waiting = this.#options.hasWork();
    if (this.#inFlight === 0) {
      this.#heldSince = undefined;
      this.#catchingUp = false;
    } else if (!waiting) {
      // the hold counts from work held back, not from an earlier burst's
      this.#heldSince = undefined;
    }
    if (!waiting) {
      if (++this.#idleTicks >= IDLE_TICKS_BEFORE_STOP) this.stop();
      return;
    }
    this.#idleTicks = 0;
    if (this.#inFlight === 0 || this.#catchingUp) {
      this.#start(true);
      return;
    }
    const now = performance.now();
    this.#heldSince ??= now;
    if (now - this.#heldSince >= this.#options.maxHoldMs) {
      this.#catchingUp = true;
      this.#start(true);
    }
  }

  /** Starts the loop unless it runs: in this turn (a tick's, flush's) or the next. */
  #start(now: boolean): void {
    this.#running ??= this.#loop(now);
  }

  async #loop(now: boolean): Promise<void> {
    const { step, sliceMs, hasWork } = this.#options;
    if (!now) await new Promise<void>((resolve) => nextTurn(resolve));
    while (this.#mayWork() && hasWork()) {
      const end = performance.now() + sliceMs;
      let more = true;
      do {
        try {
          more = await step();
        } catch {
          more = hasWork();
        }
        // a step that waited for the disk may end after a call has started: that call goes first
      } while (more && performance.now() < end && this.#mayWork());
      if (!more && !hasWork()) break;
      await new Promise<void>((resolve) => nextTurn(resolve));
    }
    this.#running = undefined;
  }

  #mayWork(): boolean {
    return this.#inFlight === 0 || this.#catchingUp || this.#flushing > 0;
  }
}
