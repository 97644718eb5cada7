import { HalError, errorMessage } from '@hal/types';
import type { TransportStats } from '@hal/types';
import type { Logger } from '@hal/types';
import type { DecodeResult, WireReply } from '../protocol/codec.js';

/** How long to wait for a reply before resending, ms (protocol 1.0, section 4). */
export const DEFAULT_REPLY_TIMEOUT_MS = 2000;
/** How many times a request is sent before it is given up (same `seq` each time). */
export const DEFAULT_ATTEMPTS = 3;

/** Per-request overrides. */
/**
 * NOT_CONNECTED for a link that could not be opened, with the system's own reason in the message
 * (its first line: `No such file or directory`, `getaddrinfo ENOTFOUND host`), since that, not a
 * timeout, is what the user acts on; the errno, where there is one, in the details.
 */
export function linkOpenError(
  what: string,
  cause: unknown,
  details: Record<string, unknown>,
): HalError {
  const reason = errorMessage(cause).split('\n', 1)[0];
  const errno = (cause as NodeJS.ErrnoException | undefined)?.code;
  return new HalError('NOT_CONNECTED', `${what}: ${reason}`, {
    cause,
    details: { ...details, ...(typeof errno === 'string' ? { errno } : {}) },
  });
}

export interface RequestOptions {
  /** Wait for a reply this long per attempt, ms. */
  timeoutMs?: number;
  /** Send at most this many times. */
  attempts?: number;
  /**
   * For a caller that resends a request itself, one transport request per attempt (the hello,
   * which looks at each failed attempt before the next): which of its attempts this is. Its
   * sends after the first count as retries, and running out counts as a timeout only on the
   * caller's last attempt, so the statistics read as for one request resent by the transport.
   */
  callerAttempt?: { attempt: number; of: number };
}

/** The request defaults a transport's own options set (only the fields given). */
export function requestDefaults(options: RequestOptions): RequestOptions {
  const defaults: RequestOptions = {};
  if (options.timeoutMs !== undefined) defaults.timeoutMs = options.timeoutMs;
  if (options.attempts !== undefined) defaults.attempts = options.attempts;
  return defaults;
}

// the link's statistics are part of the contract: the recorder reads them from any HAL by shape
export type { SerialLinkStats, TransportStats } from '@hal/types';

/**
 * A link to the robot. It sends one encoded request and resolves with the reply that echoes its
 * `seq`, resending the very same bytes after each timeout (so the robot's reply memory makes a
 * retry exactly-once). It never throws on bad input: an undecodable or unexpected inbound message
 * is counted in `stats().dropped` and ignored.
 */
export interface Transport {
  /** Which kind of link this is. */
  readonly type: string;
  /**
   * Sends `bytes` (a request carrying `seq`) and resolves with the decoded reply echoing `seq`.
   * Rejects with a HalError: TIMEOUT after every attempt, NOT_CONNECTED once closed.
   */
  request(seq: number, bytes: Uint8Array, options?: RequestOptions): Promise<WireReply>;
  /** Round-trip statistics so far. */
  stats(): TransportStats;
  /** Releases the socket or port; pending requests reject with NOT_CONNECTED. Idempotent. */
  close(): Promise<void>;
}

/** What a transport is given when it connects. */
export interface TransportContext {
  /** Decodes (and authenticates) one inbound message. */
  decode(bytes: Uint8Array): DecodeResult;
  logger: Logger;
}

/**
 * A transport description, made by a factory function (`udpTransport(...)`,
 * `serialTransport(...)`, `mockRobot.transport()`); PhysicalHAL connects it when it initialises.
 */
export interface TransportFactory<T extends string = string> {
  readonly type: T;
  connect(context: TransportContext): Promise<Transport>;
}

/** A sorted-on-demand window of round-trip samples. */
export class RttWindow {
  readonly #samples: number[] = [];
  readonly #size: number;
  #next = 0;

  constructor(size = 2048) {
    this.#size = size;
  }

  add(ms: number): void {
    if (this.#samples.length < this.#size) this.#samples.push(ms);
    else this.#samples[this.#next] = ms;
    this.#next = (this.#next + 1) % this.#size;
  }

  percentile(p: number): number {
    if (this.#samples.length === 0) return 0;
    const sorted = [...this.#samples].sort((a, b) => a - b);
    const index = Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1);
    return sorted[Math.max(0, index)] ?? 0;
  }
}

/** Reports the end of one send: with the error when it failed. */
export type SendDone = (error?: unknown) => void;

/** One request in flight: its attempt loop, as state rather than as a chain of promises. */
interface Pending {
  readonly seq: number;
  readonly send: (done: SendDone) => void;
  readonly attempts: number;
  readonly timeoutMs: number;
  readonly resolve: (reply: WireReply) => void;
  readonly reject: (error: unknown) => void;
  attempt: number;
  /** The caller's own attempt this request is, when it resends it itself. */
  readonly callerAttempt: { attempt: number; of: number } | undefined;
  sentAt: number;
  /** When this attempt times out (on the matcher's clock); Infinity while the send is under way. */
  deadline: number;
  lastError: unknown;
}

/**
 * The request/reply half both transports share: matching replies to pending requests by their
 * echoed `seq`, the attempt loop with its timeouts, and the statistics.
 *
 * A request is one promise and one record; its timeouts share one timer, armed for the earliest
 * deadline and left running when a reply comes (it re-arms itself for whatever is then due), so a
 * round trip arms and clears no timer of its own and allocates no promise per attempt: on a fast
 * link the timer fires about once per timeout, not once per request.
 */
export class ReplyMatcher {
  /**
   * The requests in flight, in no order: one or two at a time (a command and a stop on the safety
   * lane), so a scan is as fast as a lookup, and unlike a Map, whose deleted slots fill its table
   * until it is rebuilt, adding and removing allocates nothing.
   */
  readonly #pending: Pending[] = [];
  readonly #rtt = new RttWindow();
  readonly #now: () => number;
  #closed = false;
  #timer: ReturnType<typeof setTimeout> | undefined;
  /** When the timer fires (matcher clock); Infinity when it is not armed. */
  #timerDue = Infinity;
  readonly counts = { sent: 0, received: 0, timeouts: 0, retries: 0, dropped: 0 };

  constructor(now: () => number = () => performance.now()) {
    this.#now = now;
  }

  /** Feeds one decoded inbound message; returns false (and counts it) when it answers nothing. */
  deliver(result: DecodeResult): boolean {
    if (!result.ok) {
      this.counts.dropped += 1;
      return false;
    }
    const seq = result.reply.seq;
    const pending = seq === undefined ? undefined : this.#find(seq);
    if (pending === undefined) {
      this.counts.dropped += 1;
      return false;
    }
    this.#finish(pending);
    this.counts.received += 1;
    this.#rtt.add(this.#now() - pending.sentAt);
    pending.resolve(result.reply);
    return true;
  }

  /**
   * Runs the attempt loop: `send` is called once per attempt (it may itself wait, e.g. for a
   * serial ACK, and an attempt whose send fails counts as used); after a successful send each
   * attempt waits `timeoutMs` for the reply.
   */
  request(
    seq: number,
    send: () => Promise<void>,
    options: RequestOptions = {},
  ): Promise<WireReply> {
    return this.requestWith(
      seq,
      (done) => {
        send().then(
          () => done(),
          (error: unknown) => done(error ?? new Error('the send failed')),
        );
      },
      options,
    );
  }

  /**
   * {@link request} with a send that reports its end through a callback (`done()`, or
   * `done(error)`), as a socket does: no promise per attempt.
   */
  requestWith(
    seq: number,
    send: (done: SendDone) => void,
    options: RequestOptions = {},
  ): Promise<WireReply> {
    if (this.#closed) {
      return Promise.reject(new HalError('NOT_CONNECTED', 'the transport is closed'));
    }
    if (this.#find(seq) !== undefined) {
      return Promise.reject(
        new HalError('INVALID_PARAMETER', `a request with seq ${seq} is already pending`),
      );
    }
    return new Promise<WireReply>((resolve, reject) => {
      const entry: Pending = {
        seq,
        send,
        attempts: options.attempts ?? DEFAULT_ATTEMPTS,
        timeoutMs: options.timeoutMs ?? DEFAULT_REPLY_TIMEOUT_MS,
        resolve,
        reject,
        attempt: 0,
        callerAttempt: options.callerAttempt,
        sentAt: 0, // set by each attempt
        deadline: Infinity,
        lastError: undefined,
      };
      this.#pending.push(entry);
      this.#attempt(entry);
    });
  }

  /** Sends the next attempt of `entry`, or gives it up when none is left. */
  #attempt(entry: Pending): void {
    if (entry.attempt >= entry.attempts) {
      this.#finish(entry);
      const caller = entry.callerAttempt;
      if (caller === undefined || caller.attempt >= caller.of) this.counts.timeouts += 1;
      entry.reject(
        new HalError(
          'TIMEOUT',
          `no reply to request ${entry.seq} after ${entry.attempts} attempts of ${entry.timeoutMs} ms`,
          {
            details: { seq: entry.seq, attempts: entry.attempts, timeoutMs: entry.timeoutMs },
            cause: entry.lastError,
          },
        ),
      );
      return;
    }
    entry.attempt += 1;
    const attempt = entry.attempt;
    if (attempt > 1 || (entry.callerAttempt?.attempt ?? 1) > 1) this.counts.retries += 1;
    entry.sentAt = this.#now();
    entry.deadline = Infinity;
    this.counts.sent += 1;
    try {
      // an inline arrow: a named closure per attempt would cost more under some transpilers
      entry.send((error?: unknown) => this.#sent(entry, attempt, error));
    } catch (error) {
      this.#sent(entry, attempt, error ?? new Error('the send failed'));
    }
  }

  /** An attempt's send has ended: wait for its reply, or try again at once if it failed. */
  #sent(entry: Pending, attempt: number, error: unknown): void {
    // answered, closed or given up meanwhile, or a late report of an older attempt
    if (this.#find(entry.seq) !== entry || entry.attempt !== attempt) return;
    if (error !== undefined) {
      entry.lastError = error;
      this.#attempt(entry);
      return;
    }
    entry.deadline = this.#now() + entry.timeoutMs;
    this.#arm(entry.deadline);
  }

  /** The pending request numbered `seq`. */
  #find(seq: number): Pending | undefined {
    for (const entry of this.#pending) if (entry.seq === seq) return entry;
    return undefined;
  }

  /** Takes `entry` out of the pending requests. */
  #finish(entry: Pending): void {
    const index = this.#pending.indexOf(entry);
    if (index >= 0) {
      // order does not matter: the last one takes its place
      const last = this.#pending.pop()!;
      if (index < this.#pending.length) this.#pending[index] = last;
    }
    entry.deadline = Infinity;
    if (this.#pending.length === 0) this.#timer?.unref();
  }

  /** Makes the shared timer fire by `deadline`. */
  #arm(deadline: number): void {
    if (this.#timer !== undefined && this.#timerDue <= deadline) {
      this.#timer.ref(); // a request waits on it again
      return;
    }
    clearTimeout(this.#timer);
    this.#timerDue = deadline;
    this.#timer = setTimeout(() => this.#expire(), Math.max(0, deadline - this.#now()));
  }

  /** Times out every attempt whose deadline has passed, and re-arms for the next one. */
  #expire(): void {
    this.#timer = undefined;
    this.#timerDue = Infinity;
    const now = this.#now();
    let next = Infinity;
    for (const entry of [...this.#pending]) {
      if (entry.deadline <= now) this.#attempt(entry);
      else if (entry.deadline < next) next = entry.deadline;
    }
    // #attempt may have armed the timer for a resend already
    if (next !== Infinity) this.#arm(next);
  }

  /** Rejects every pending and later request with NOT_CONNECTED. */
  close(): void {
    this.#closed = true;
    clearTimeout(this.#timer);
    this.#timer = undefined;
    this.#timerDue = Infinity;
    const pending = this.#pending.splice(0);
    for (const entry of pending) {
      entry.reject(new HalError('NOT_CONNECTED', 'the transport is closed'));
    }
  }

  stats(): TransportStats {
    return {
      ...this.counts,
      rttP50Ms: this.#rtt.percentile(50),
      rttP99Ms: this.#rtt.percentile(99),
    };
  }
}
