import type { MessageAuthenticator } from '../protocol/auth.js';
import { appendMac, splitMac } from '../protocol/auth.js';
import { MAX_MESSAGE_BYTES } from '../protocol/codec.js';
import { Refusal } from './refusal.js';
import type { Json } from './refusal.js';

/** The envelope fields of a request, as far as they could be read. */
export interface Envelope {
  cmd: string | undefined;
  seq: number | undefined;
  sid: number | undefined;
}

/** No envelope: the request could not be read. */
export const NO_ENVELOPE: Envelope = { cmd: undefined, seq: undefined, sid: undefined };

const encoder = new TextEncoder();
const decoder = new TextDecoder();

/** The envelope fields of a request, each only when it has the right JSON type. */
export function envelopeOf(request: Json): Envelope {
  return {
    cmd: typeof request['cmd'] === 'string' ? request['cmd'] : undefined,
    seq: typeof request['seq'] === 'number' ? request['seq'] : undefined,
    sid: typeof request['sid'] === 'number' ? request['sid'] : undefined,
  };
}

/**
 * The robot's end of the message format: reads requests (MAC, JSON object, no repeated key) and
 * writes replies (MACed when a key is set).
 */
export class MockWire {
  readonly #auth: MessageAuthenticator | undefined;

  constructor(auth: MessageAuthenticator | undefined) {
    this.#auth = auth;
  }

  /** Whether messages must carry a MAC. */
  get authenticated(): boolean {
    return this.#auth !== undefined;
  }

  /** One request, or the refusal to answer it with (AUTH_FAILED, MALFORMED). */
  read(bytes: Uint8Array): Json | Refusal {
    if (bytes.length > MAX_MESSAGE_BYTES)
      return new Refusal('MALFORMED', `message longer than ${MAX_MESSAGE_BYTES} bytes`);
    let json = bytes;
    if (this.#auth !== undefined) {
      const signed = splitMac(bytes);
      if (
        signed === undefined ||
        signed.json.length === 0 ||
        !this.#auth.verify(signed.json, signed.mac)
      )
        return new Refusal('AUTH_FAILED', 'missing or wrong MAC');
      json = signed.json;
    }
    try {
      const text = decoder.decode(json);
      if (hasDuplicateKey(text)) throw new Error('duplicated key');
      const value: unknown = JSON.parse(text);
      if (value === null || typeof value !== 'object' || Array.isArray(value))
        throw new Error('not an object');
      return value as Json;
    } catch {
      return new Refusal('MALFORMED', 'not a JSON object');
    }
  }

  /** The bytes of a reply. */
  reply(value: Json): Uint8Array {
    const json = encoder.encode(JSON.stringify(value));
    return this.#auth === undefined ? json : appendMac(json, this.#auth);
  }

  /** The bytes of an error reply to a request with this envelope. */
  error(envelope: Envelope, refusal: Refusal): Uint8Array {
    const { seq, sid, cmd } = envelope;
    return this.reply({
      seq,
      sid,
      ok: false,
      cmd,
      error: { code: refusal.code, message: refusal.message, details: refusal.details },
    });
  }
}

/** Whether a JSON text repeats a key within one object (the protocol calls that MALFORMED). */
function hasDuplicateKey(text: string): boolean {
  const stack: Array<Set<string> | undefined> = [];
  let expectKey = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === '"') {
      let end = i + 1;
      while (end < text.length && text[end] !== '"') end += text[end] === '\\' ? 2 : 1;
      const keys = stack[stack.length - 1];
      if (expectKey && keys !== undefined) {
        const key = text.slice(i + 1, end);
        if (keys.has(key)) return true;
        keys.add(key);
      }
      expectKey = false;
      i = end;
    } else if (c === '{') {
      stack.push(new Set());
      expectKey = true;
    } else if (c === '[') {
      stack.push(undefined);
    } else if (c === '}' || c === ']') {
      stack.pop();
    } else if (c === ',') {
      expectKey = stack[stack.length - 1] !== undefined;
    }
  }
  return false;
}
