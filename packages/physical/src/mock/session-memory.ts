import { Refusal } from './refusal.js';
import type { Envelope } from './wire.js';

/** How many executed requests' replies a session remembers (protocol 1.1, section 4). */
const MEMORY = 16;

/** What the session rules decide for one request (other than `hello`). */
export type Admission =
  | { kind: 'refuse'; refusal: Refusal }
  /** A retry of a remembered request: its reply, byte for byte, and no execution. */
  | { kind: 'replay'; reply: Uint8Array }
  /** Execute it; `remember` its reply under its seq; whether it counts as `contact` from the host. */
  | { kind: 'execute'; remember: boolean; contact: boolean }
  /**
   * A motion command numbered below a stop already executed (protocol 1.1, section 4.1): not
   * executed; the refusal is its reply, remembered like any other.
   */
  | { kind: 'overtaken'; refusal: Refusal };

/** Commands that move the wheels. */
const MOTION_COMMANDS: ReadonlySet<string> = new Set([
  'move_steps',
  'move_cm',
  'rotate_deg',
  'drive',
]);

/**
 * The robot's session: the current `sid`, the highest `seq` executed and the replies of the last
 * 16 requests, so that a resent request is answered from memory and executed exactly once; and
 * the `hello` that opened the session, so that a resent `hello` keeps it.
 */
export class SessionMemory {
  #sid = 0;
  #lastSeq = 0;
  readonly #replies = new Map<number, Uint8Array>();
  #helloKey = '';
  #helloReply: Uint8Array | undefined;
  /** The highest seq of a stop or e-stop executed in this session, and which it was. */
  #fence = 0;
  #fenceBy: 'stop' | 'estop' = 'stop';

  /**
   * Applies the session rules, in order, to a request other than `hello`. `authenticated`: a key
   * is set, so every request needs `seq` (seed-style requests run only in the unauthenticated
   * opt-out) and `reset_estop` needs the session.
   */
  admit(envelope: Envelope, authenticated: boolean): Admission {
    const { cmd, seq, sid } = envelope;
    // with a key, a replayed reset must not clear an e-stop: reset_estop then needs the session
    const safety = cmd === 'stop' || cmd === 'estop' || (cmd === 'reset_estop' && !authenticated);
    const seedStyle = seq === undefined && sid === undefined;
    if (seedStyle && authenticated) {
      return refuse('AUTH_FAILED', '"seq" is required when a key is configured');
    }
    // safety commands, and seed-style requests, skip the session rules and are not remembered
    const session = !safety && !seedStyle;
    if (!seedStyle && (seq === undefined || sid === undefined)) {
      return refuse(
        'SESSION_MISMATCH',
        '"sid" and "seq" must be given together; send hello to open a session',
      );
    }
    if (session) {
      if (sid !== this.#sid || this.#sid === 0) {
        return refuse('SESSION_MISMATCH', 'unknown session; send hello');
      }
      const remembered = this.#replies.get(seq!);
      if (remembered !== undefined) return { kind: 'replay', reply: remembered };
      if (seq! <= this.#lastSeq) {
        return refuse('STALE_SEQUENCE', 'stale seq', { seq, last_seq: this.#lastSeq });
      }
      if (cmd !== undefined && MOTION_COMMANDS.has(cmd) && seq! < this.#fence) {
        const estop = this.#fenceBy === 'estop';
        return {
          kind: 'overtaken',
          refusal: new Refusal(
            estop ? 'EMERGENCY_STOPPED' : 'INTERRUPTED',
            `"${cmd}" was sent before ${estop ? 'an estop' : 'a stop'} that was already executed`,
            { stop_seq: this.#fence },
          ),
        };
      }
    } else if (
      (cmd === 'stop' || cmd === 'estop') &&
      seq !== undefined &&
      this.#sid !== 0 &&
      sid === this.#sid &&
      seq >= this.#fence
    ) {
      // the safety lane: executed whatever its seq, never remembered; it fences older motion
      this.#fence = seq;
      this.#fenceBy = cmd;
    }
    // only requests that pass the session rules, and seed-style ones, count as contact
    return {
      kind: 'execute',
      remember: session,
      contact: session || seedStyle || sid === this.#sid,
    };
  }

  /** Remembers the reply of an executed request; its seq becomes the session's highest. */
  remember(seq: number, reply: Uint8Array): void {
    this.#lastSeq = seq;
    this.#replies.set(seq, reply);
    if (this.#replies.size > MEMORY)
      this.#replies.delete(this.#replies.keys().next().value as number);
  }

  /** The stored reply when this `hello` repeats the nonce and seq of the one that opened the session. */
  helloRetry(nonce: string | undefined, seq: number | undefined): Uint8Array | undefined {
    if (
      this.#helloReply !== undefined &&
      nonce !== undefined &&
      helloKey(nonce, seq) === this.#helloKey
    )
      return this.#helloReply;
    return undefined;
  }

  /** Opens a new session after a `hello` with this seq, forgetting the old one; returns its sid. */
  open(seq: number | undefined): number {
    this.#sid = 1 + Math.floor(Math.random() * 0xfffffffe);
    this.#lastSeq = seq ?? 0;
    this.#fence = 0;
    this.#replies.clear();
    return this.#sid;
  }

  /** Keeps the reply of the `hello` that opened the session, for its retries. */
  openedBy(nonce: string | undefined, seq: number | undefined, reply: Uint8Array): void {
    this.#helloKey = helloKey(nonce, seq);
    this.#helloReply = reply;
  }

  /** A power cycle: no session. */
  forget(): void {
    this.#sid = 0;
    this.#fence = 0;
    this.#helloReply = undefined;
    this.#replies.clear();
  }
}

function helloKey(nonce: string | undefined, seq: number | undefined): string {
  return `${nonce ?? ''}/${seq ?? ''}`;
}

function refuse(code: string, message: string, details?: Record<string, unknown>): Admission {
  return { kind: 'refuse', refusal: new Refusal(code, message, details) };
}
