import { HalError, sanitizeEstopReason } from '@hal/types';
import type { MessageAuthenticator } from './auth.js';
import { MAC_SUFFIX_LENGTH, splitMac, writeMac } from './auth.js';
import { BytePool } from './byte-pool.js';
import { parseEnvelope } from './envelope.js';
import type { ReplyEnvelope } from './schemas.js';

/** The largest message either side sends: 1024 bytes, MAC suffix included. */
export const MAX_MESSAGE_BYTES = 1024;

const encoder = new TextEncoder();
const decoder = new TextDecoder('utf-8', { fatal: true });

/** A decoded reply: the envelope fields plus every other field the device sent. */
export type WireReply = ReplyEnvelope & Record<string, unknown>;

/** The outcome of decoding an inbound message: never throws. */
export type DecodeResult = { ok: true; reply: WireReply } | { ok: false; error: HalError };

function tooLong(message: Record<string, unknown>, bytes: number): HalError {
  return new HalError(
    'RANGE_EXCEEDED',
    `the "${String(message['cmd'])}" message is ${bytes} bytes; the protocol allows at most ${MAX_MESSAGE_BYTES}`,
    { details: { bytes, max: MAX_MESSAGE_BYTES } },
  );
}

/** Encodes and (when a key is configured) authenticates requests, and decodes replies. */
export class MessageCodec {
  readonly #auth: MessageAuthenticator | undefined;
  /** Where requests are written: a view each, not an ArrayBuffer each (see BytePool). */
  readonly #pool = new BytePool();
  /**
   * Inbound messages refused for their MAC, by why: `unsigned` carried none (the device has no
   * key), `mismatched` carried one that is not ours (the device has another key). They say a
   * device answered, even though what it said cannot be trusted.
   */
  readonly macRejections = { unsigned: 0, mismatched: 0 };

  constructor(auth?: MessageAuthenticator) {
    this.#auth = auth;
  }

  /** Whether messages carry a MAC. */
  get authenticated(): boolean {
    return this.#auth !== undefined;
  }

  /**
   * The bytes of one request: `{"cmd":...,"seq":...,"sid":...,<params>}` plus the MAC suffix when
   * a key is set. Throws RANGE_EXCEEDED when the message would be longer than 1024 bytes, except
   * for `stop` and `estop`, which always encode.
   */
  encode(message: Record<string, unknown>): Uint8Array {
    const cmd = message['cmd'];
    if (cmd === 'stop' || cmd === 'estop') return this.#encodeSafety(message);
    return this.#encodeChecked(message);
  }

  /**
   * A `stop` or `estop` always encodes (protocol section 4.1): the reason is sanitized to at most
   * 63 UTF-8 bytes, and should the message still be too long, only the envelope and the reason
   * are kept.
   */
  #encodeSafety(message: Record<string, unknown>): Uint8Array {
    const safe: Record<string, unknown> = { ...message };
    if (message['cmd'] === 'estop') safe['reason'] = sanitizeEstopReason(message['reason']);
    const bytes = this.#encodeOrUndefined(safe);
    if (bytes !== undefined) return bytes;
    const minimal: Record<string, unknown> = { cmd: message['cmd'] };
    for (const key of ['seq', 'sid', 'reason']) {
      if (safe[key] !== undefined) minimal[key] = safe[key];
    }
    return this.#encodeChecked(minimal);
  }

  #encodeOrUndefined(message: Record<string, unknown>): Uint8Array | undefined {
    try {
      return this.#encodeChecked(message);
    } catch {
      return undefined;
    }
  }

  #encodeChecked(message: Record<string, unknown>): Uint8Array {
    const json = JSON.stringify(message);
    const suffix = this.#auth === undefined ? 0 : MAC_SUFFIX_LENGTH;
    // UTF-8 takes at least one byte per UTF-16 code unit: a longer text can only be too long
    if (json.length + suffix > MAX_MESSAGE_BYTES) {
      throw tooLong(message, encoder.encode(json).length + suffix);
    }
    // at most three bytes per code unit (a surrogate pair: four for two), so it always fits
    const room = this.#pool.room(json.length * 3 + suffix);
    const { written } = encoder.encodeInto(json, room);
    const length = this.#auth === undefined ? written : writeMac(room, written, this.#auth);
    if (length > MAX_MESSAGE_BYTES) throw tooLong(message, length);
    return this.#pool.take(length);
  }

  /**
   * Decodes one inbound message: checks the MAC (when a key is set), the UTF-8, the JSON and the
   * envelope schema. Malformed input is an error value (MALFORMED, or AUTH_FAILED for a missing
   * or wrong MAC), never an exception.
   */
  decode(bytes: Uint8Array): DecodeResult {
    const signed = splitMac(bytes);
    let json = bytes;
    if (this.#auth === undefined) {
      // a device with a key MACs even its AUTH_FAILED reply: read it, to say why
      if (signed !== undefined) json = signed.json;
    } else {
      if (signed === undefined) {
        this.macRejections.unsigned += 1;
        return { ok: false, error: new HalError('AUTH_FAILED', 'reply has no MAC suffix') };
      }
      json = signed.json;
      if (!this.#auth.verify(json, signed.mac)) {
        this.macRejections.mismatched += 1;
        return { ok: false, error: new HalError('AUTH_FAILED', 'reply MAC does not match') };
      }
    }
    let value: unknown;
    try {
      value = JSON.parse(decoder.decode(json));
    } catch (cause) {
      return {
        ok: false,
        error: new HalError('MALFORMED', 'reply is not UTF-8 JSON', { cause }),
      };
    }
    const parsed = parseEnvelope(value);
    if (!parsed.success) {
      const issue = parsed.error.issues[0];
      return {
        ok: false,
        error: new HalError(
          'MALFORMED',
          `reply envelope is invalid: ${issue?.path.join('.') || 'message'} ${issue?.message ?? ''}`.trim(),
          { details: { issues: parsed.error.issues.length } },
        ),
      };
    }
    return { ok: true, reply: parsed.data as WireReply };
  }
}
