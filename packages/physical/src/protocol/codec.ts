import { HalError } from '@hal/types';
import type { MessageAuthenticator } from './auth.js';
import { MAC_SUFFIX_LENGTH } from './auth.js';
import { ReplyEnvelopeSchema } from './schemas.js';
import type { ReplyEnvelope } from './schemas.js';

/** The largest message either side sends: 1024 bytes, MAC suffix included. */
export const MAX_MESSAGE_BYTES = 1024;

const encoder = new TextEncoder();
const decoder = new TextDecoder('utf-8', { fatal: true });
const HASH = 0x23;

/** A decoded reply: the envelope fields plus every other field the device sent. */
export type WireReply = ReplyEnvelope & Record<string, unknown>;

/** The outcome of decoding an inbound message: never throws. */
export type DecodeResult = { ok: true; reply: WireReply } | { ok: false; error: HalError };

function hex(bytes: Uint8Array): boolean {
  for (const b of bytes) {
    const digit = b >= 0x30 && b <= 0x39;
    const lower = b >= 0x61 && b <= 0x66;
    if (!digit && !lower) return false;
  }
  return true;
}

/** Encodes and (when a key is configured) authenticates requests, and decodes replies. */
export class MessageCodec {
  readonly #auth: MessageAuthenticator | undefined;

  constructor(auth?: MessageAuthenticator) {
    this.#auth = auth;
  }

  /** Whether messages carry a MAC. */
  get authenticated(): boolean {
    return this.#auth !== undefined;
  }

  /**
   * The bytes of one request: `{"cmd":...,"seq":...,"sid":...,<params>}` plus the MAC suffix when
   * a key is set. Throws RANGE_EXCEEDED when the message would be longer than 1024 bytes.
   */
  encode(message: Record<string, unknown>): Uint8Array {
    const json = encoder.encode(JSON.stringify(message));
    let bytes = json;
    if (this.#auth !== undefined) {
      const suffix = encoder.encode(`#${this.#auth.mac(json)}`);
      bytes = new Uint8Array(json.length + suffix.length);
      bytes.set(json, 0);
      bytes.set(suffix, json.length);
    }
    if (bytes.length > MAX_MESSAGE_BYTES) {
      throw new HalError(
        'RANGE_EXCEEDED',
        `the "${String(message['cmd'])}" message is ${bytes.length} bytes; the protocol allows at most ${MAX_MESSAGE_BYTES}`,
        { details: { bytes: bytes.length, max: MAX_MESSAGE_BYTES } },
      );
    }
    return bytes;
  }

  /**
   * Decodes one inbound message: checks the MAC (when a key is set), the UTF-8, the JSON and the
   * envelope schema. Malformed input is an error value (MALFORMED, or AUTH_FAILED for a missing
   * or wrong MAC), never an exception.
   */
  decode(bytes: Uint8Array): DecodeResult {
    let json = bytes;
    if (this.#auth === undefined) {
      // a device with a key MACs even its AUTH_FAILED reply: read it, to say why
      const at = bytes.length - MAC_SUFFIX_LENGTH;
      if (at > 0 && bytes[at] === HASH && hex(bytes.subarray(at + 1))) json = bytes.subarray(0, at);
    } else {
      const at = bytes.length - MAC_SUFFIX_LENGTH;
      const mac = bytes.subarray(at + 1);
      if (at < 0 || bytes[at] !== HASH || !hex(mac)) {
        return { ok: false, error: new HalError('AUTH_FAILED', 'reply has no MAC suffix') };
      }
      json = bytes.subarray(0, at);
      const expected = this.#auth.mac(json);
      if (decoder.decode(mac) !== expected) {
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
    const parsed = ReplyEnvelopeSchema.safeParse(value);
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
