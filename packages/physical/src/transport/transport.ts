import { HalError } from '@hal/types';
import type { Logger } from '../logger.js';
import type { DecodeResult, WireReply } from '../protocol/codec.js';

/** How long to wait for a reply before resending, ms (protocol 1.0, section 4). */
export const DEFAULT_REPLY_TIMEOUT_MS = 2000;
/** How many times a request is sent before it is given up (same `seq` each time). */
export const DEFAULT_ATTEMPTS = 3;

/** Per-request overrides. */
export interface RequestOptions {
  /** Wait for a reply this long per attempt, ms. */
  timeoutMs?: number;
  /** Send at most this many times. */
  attempts?: number;
}

/** The request defaults a transport's own options set (only the fields given). */
export function requestDefaults(options: RequestOptions): RequestOptions {
  const defaults: RequestOptions = {};
  if (options.timeoutMs !== undefined) defaults.timeoutMs = options.timeoutMs;
  if (options.attempts !== undefined) defaults.attempts = options.attempts;
  return defaults;
}

/** Round-trip statistics every transport keeps. */
export interface TransportStats {
  /** Requests sent, retries included. */
  sent: number;
  /** Replies that answered a pending request. */
  received: number;
  /** Requests given up after every attempt. */
  timeouts: number;
  /** Resends of a request (same bytes, same `seq`). */
  retries: number;
  /** Inbound messages dropped: undecodable, failed MAC, or answering no pending request. */
  dropped: number;
  /** Median round trip of answered requests, ms (from the attempt that was answered). */
  rttP50Ms: number;
  /** 99th percentile round trip, ms. */
  rttP99Ms: number;
}

/** Extra statistics of the serial link. */
export interface SerialLinkStats {
  framesSent: number;
  framesReceived: number;
  acksSent: number;
  acksReceived: number;
  /** Frames resent because their ACK did not come in time. */
  frameRetries: number;
  /** Frames given up after every attempt. */
  frameTimeouts: number;
  checksumErrors: number;
  /** Bytes skipped while hunting for a frame (garbage, bad headers). */
  resyncBytes: number;
  /** Duplicate DATA frames (same link seq) acknowledged but not delivered again. */
  duplicateFrames: number;
}

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

interface Pending {
  resolve(reply: WireReply): void;
  sentAt: number;
}

/**
 * The request/reply half both transports share: matching replies to pending requests by their
 * echoed `seq`, the attempt loop with its timeouts, and the statistics.
 */
export class ReplyMatcher {
  readonly #pending = new Map<number, Pending>();
  /** Wakes the requests in flight when the transport closes. */
  readonly #closeListeners = new Set<() => void>();
  readonly #rtt = new RttWindow();
  readonly #now: () => number;
  #closed = false;
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
    const pending = seq === undefined ? undefined : this.#pending.get(seq);
    if (seq === undefined || pending === undefined) {
      this.counts.dropped += 1;
      return false;
    }
    this.#pending.delete(seq);
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
  async request(
    seq: number,
    send: () => Promise<void>,
    options: RequestOptions = {},
  ): Promise<WireReply> {
    const attempts = options.attempts ?? DEFAULT_ATTEMPTS;
    const timeoutMs = options.timeoutMs ?? DEFAULT_REPLY_TIMEOUT_MS;
    if (this.#closed) throw new HalError('NOT_CONNECTED', 'the transport is closed');
    if (this.#pending.has(seq)) {
      throw new HalError('INVALID_PARAMETER', `a request with seq ${seq} is already pending`);
    }
    let resolveReply!: (reply: WireReply) => void;
    const answered = new Promise<WireReply>((resolve) => {
      resolveReply = resolve;
    });
    const entry: Pending = { resolve: resolveReply, sentAt: this.#now() };
    this.#pending.set(seq, entry);
    // A close signal of this request's own, dropped when it ends: racing every request against
    // one long-lived promise would add a reaction to it each time, kept until the transport
    // closes (a leak of about 1 KB per request on a long-running host).
    let onClose!: () => void;
    const closedSignal = new Promise<'closed'>((resolve) => {
      onClose = () => resolve('closed');
    });
    this.#closeListeners.add(onClose);
    let lastError: unknown;
    try {
      for (let attempt = 1; attempt <= attempts; attempt++) {
        if (this.#closed) throw new HalError('NOT_CONNECTED', 'the transport is closed');
        if (attempt > 1) this.counts.retries += 1;
        entry.sentAt = this.#now();
        this.counts.sent += 1;
        const sending = await Promise.race([
          send().then(
            () => 'sent' as const,
            (error: unknown) => {
              lastError = error;
              return 'failed' as const;
            },
          ),
          answered,
          closedSignal,
        ]);
        if (sending === 'closed') throw new HalError('NOT_CONNECTED', 'the transport is closed');
        if (typeof sending === 'object') return sending;
        if (sending === 'failed') continue;
        let timer: ReturnType<typeof setTimeout> | undefined;
        try {
          const outcome = await Promise.race([
            answered,
            closedSignal,
            new Promise<'timeout'>((resolve) => {
              timer = setTimeout(() => resolve('timeout'), timeoutMs);
            }),
          ]);
          if (outcome === 'closed') throw new HalError('NOT_CONNECTED', 'the transport is closed');
          if (outcome !== 'timeout') return outcome;
        } finally {
          clearTimeout(timer);
        }
      }
      this.counts.timeouts += 1;
      throw new HalError(
        'TIMEOUT',
        `no reply to request ${seq} after ${attempts} attempts of ${timeoutMs} ms`,
        { details: { seq, attempts, timeoutMs }, cause: lastError },
      );
    } finally {
      this.#closeListeners.delete(onClose);
      if (this.#pending.get(seq) === entry) this.#pending.delete(seq);
    }
  }

  /** Rejects every pending and later request with NOT_CONNECTED. */
  close(): void {
    this.#closed = true;
    for (const wake of this.#closeListeners) wake();
    this.#closeListeners.clear();
  }

  stats(): TransportStats {
    return {
      ...this.counts,
      rttP50Ms: this.#rtt.percentile(50),
      rttP99Ms: this.#rtt.percentile(99),
    };
  }
}
