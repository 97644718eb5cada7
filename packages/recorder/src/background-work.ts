import { nextTurn } from '@hal/types';

/** How a recorder's background work is scheduled. */
export interface BackgroundWorkOptions {
  /** Does one piece of work; resolves false when there was none left. */
  step: () => boolean | Promise<boolean>;
  /** Whether work is waiting. */
  hasWork: () => boolean;
  /**
   * The longest work waits for a moment with no call on its way (ms). Past it, while calls keep
   * coming back to back, work runs in short windows while each call waits for its reply, until
   * a moment with none on its way.
   */
  maxHoldMs: number;
  /** The longest one turn of work runs before it yields to the event loop (ms). */
  sliceMs: number;
  /** How often waiting work looks for a moment with no call on its way (ms). */
  tickMs: number;
  /** The clock calls are timed by (ms). Default `performance.now`. */
  now?: () => number;
}

/** Ticks with no work before the ticker stops (it starts again with the next work). */
const IDLE_TICKS_BEFORE_STOP = 100;
/**
 * The share of a typical call's round trip that one window of work, while the call waits for
 * its reply, may take. A round trip is mostly the robot's time: the thread that sent the call
 * waits idle for the reply, and work that ends before the reply comes delays nothing.
 */
const WINDOW_SHARE = 0.25;
/** The shortest window (ms): about one record's work, so a backlog always moves. */
const MIN_WINDOW_MS = 0.02;
/** How much of each new call's duration goes into the typical duration (a moving average). */
const TYPICAL_WEIGHT = 1 / 16;

/**
 * Runs a recorder's work (making records, encoding them, writing chunks) where it delays no
 * call. A reply that comes in while the main thread encodes or compresses waits for it; a call
 * made while no work runs is answered as fast as unrecorded.
 *
 * - **In a pause.** A call's path schedules nothing: queued work waits for a ticker (every
 *   `tickMs`) that finds no call on its way, and then runs, a slice of at most `sliceMs` at a
 *   time, until a call starts or nothing is left. (On a CPU woken from idle, arming an
 *   immediate from the call's path took about 15 µs, as much as the rest of the call's
 *   recording path.) A loop that pauses between its calls (a control loop, an agent) never
 *   meets the recording's work.
 * - **While a call waits for its reply.** Once work has waited `maxHoldMs` (calls back to back,
 *   with no pause), each call started gets one window of work in the next turn, after it has
 *   gone out: a quarter of a typical call's round trip, so the work ends while the robot is
 *   still answering. A loop that never pauses then meets the work only as a window that runs
 *   over (a finished chunk's compression), and the recording keeps up with it.
 */
export class BackgroundWork {
  readonly #options: BackgroundWorkOptions;
  #inFlight = 0;
  #running: Promise<void> | undefined;
  #windowArmed = false;
  #ticker: ReturnType<typeof setInterval> | undefined;
  #idleTicks = 0;
  /** When a tick first found work held back by a call on its way (reset by one finding none). */
  #heldSince: number | undefined;
  /** Work has waited `maxHoldMs`: it runs in windows until a tick finds no call on its way. */
  #catchingUp = false;
  #flushing = 0;
  /** A moving average of calls' durations (ms), once one has answered. */
  #typicalCallMs: number | undefined;

  constructor(options: BackgroundWorkOptions) {
    this.#options = options;
  }

  /**
   * Marks a call on its way, started at `at` (the clock's time, read now if not given); returns
   * the function that marks it answered (once), at the time it is given or now.
   */
  callStarted(at?: number): (at?: number) => void {
    const started = at ?? this.#now();
    this.callBegan();
    let ended = false;
    return (answeredAt) => {
      if (ended) return;
      ended = true;
      this.callEnded((answeredAt ?? this.#now()) - started);
    };
  }

  /**
   * Marks a call on its way, as {@link callStarted} does with no closure to allocate: for a
   * caller that pairs each with exactly one {@link callEnded} itself (a recorded call's path).
   */
  callBegan(): void {
    this.#inFlight += 1;
    if (this.#catchingUp && this.#options.hasWork()) this.#armWindow();
  }

  /** Marks a call begun with {@link callBegan} answered, after `durationMs`. */
  callEnded(durationMs: number): void {
    // one too many is ignored: a count below 0 would hold the work back for good
    if (this.#inFlight > 0) this.#inFlight -= 1;
    this.#noteDuration(durationMs);
  }

  /** There is work: it runs at the next moment with no call on its way. */
  kick(): void {
    // never in this turn: the kick comes from a call's path
    if (this.#flushing > 0) this.#start(false);
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

  /**
   * The longest one window of work may take while a call waits for its reply (ms): a quarter
   * of a typical call, within [0.02 ms, `sliceMs`]; `sliceMs` until a call has answered.
   */
  windowMs(): number {
    const typical = this.#typicalCallMs;
    if (typical === undefined) return this.#options.sliceMs;
    return Math.min(this.#options.sliceMs, Math.max(MIN_WINDOW_MS, typical * WINDOW_SHARE));
  }

  #now(): number {
    return this.#options.now?.() ?? performance.now();
  }

  #noteDuration(ms: number): void {
    // a duration a caller got wrong (NaN, < 0) would make every later window NaN long
    if (!(ms >= 0 && ms < Number.POSITIVE_INFINITY)) return;
    const typical = this.#typicalCallMs;
    // a slow call (a motion, a stall) counts as at most twice the average, so one moves it little
    this.#typicalCallMs =
      typical === undefined ? ms : typical + (Math.min(ms, 2 * typical) - typical) * TYPICAL_WEIGHT;
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
    if (this.#inFlight === 0) {
      this.#start(true);
      return;
    }
    if (!this.#catchingUp) {
      const now = performance.now();
      this.#heldSince ??= now;
      if (now - this.#heldSince < this.#options.maxHoldMs) return;
      this.#catchingUp = true;
    }
    // a call on its way for a whole tick (a motion) leaves the thread idle: a window meanwhile
    this.#running ??= this.#window();
  }

  #armWindow(): void {
    if (this.#windowArmed || this.#running !== undefined) return;
    this.#windowArmed = true;
    // the next turn: once the call has gone out and its caller waits for the reply
    nextTurn(() => {
      this.#windowArmed = false;
      this.#running ??= this.#window();
    });
  }

  /** One window of work, while calls are on their way. */
  async #window(): Promise<void> {
    await this.#steps(performance.now() + this.windowMs(), () => true);
    this.#running = undefined;
  }

  /** Starts the loop unless it runs: in this turn (a tick's, flush's) or the next. */
  #start(now: boolean): void {
    this.#running ??= this.#loop(now);
  }

  /** Slices of work until a call starts or none is left. */
  async #loop(now: boolean): Promise<void> {
    const { sliceMs, hasWork } = this.#options;
    const mayWork = (): boolean => this.#inFlight === 0 || this.#flushing > 0;
    if (!now) await new Promise<void>((resolve) => nextTurn(resolve));
    while (mayWork() && hasWork()) {
      const more = await this.#steps(performance.now() + sliceMs, mayWork);
      if (!more && !hasWork()) break;
      await new Promise<void>((resolve) => nextTurn(resolve));
    }
    this.#running = undefined;
  }

  /** Pieces of work until `end` (a time) or `mayWork()` says stop; false once none was left. */
  async #steps(end: number, mayWork: () => boolean): Promise<boolean> {
    const { step, hasWork } = this.#options;
    let more = true;
    do {
      try {
        more = await step();
      } catch {
        more = hasWork();
      }
      // a step that waited for the disk may end after a call has started: that call goes first
    } while (more && performance.now() < end && mayWork());
    return more;
  }
}
