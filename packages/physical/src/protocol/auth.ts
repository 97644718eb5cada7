import { HalError } from '@hal/types';

/**
 * Message authentication of protocol 1.1, section 8: `<json>#<mac>`, where mac is 32 lowercase hex
 * digits, the first 16 bytes of HMAC-SHA256(key, json bytes).
 */
export interface MessageAuthenticator {
  /** The 32-hex-digit MAC of `json`. */
  mac(json: Uint8Array): string;
  /**
   * Whether `mac` (32 lowercase hex digits, as read from a message) is the MAC of `json`, compared
   * in constant time: how long it takes says nothing about how much of a forged MAC was right.
   */
  verify(json: Uint8Array, mac: string): boolean;
}

/** Length of the `#` + 32 hex digits suffix. */
export const MAC_SUFFIX_LENGTH = 33;

const HASH = 0x23;
const ascii = new TextDecoder();

function isLowerHex(bytes: Uint8Array): boolean {
  for (const b of bytes) {
    const digit = b >= 0x30 && b <= 0x39;
    const lower = b >= 0x61 && b <= 0x66;
    if (!digit && !lower) return false;
  }
  return true;
}

/**
 * Splits a message that ends in a MAC suffix (`#` and 32 lowercase hex digits, which JSON never
 * ends with) into its JSON bytes and the MAC; undefined when it carries none.
 */
export function splitMac(bytes: Uint8Array): { json: Uint8Array; mac: string } | undefined {
  const at = bytes.length - MAC_SUFFIX_LENGTH;
  if (at < 0 || bytes[at] !== HASH) return undefined;
  const mac = bytes.subarray(at + 1);
  if (!isLowerHex(mac)) return undefined;
  return { json: bytes.subarray(0, at), mac: ascii.decode(mac) };
}

/** The JSON bytes followed by `#` and their MAC (written in place: one array per message). */
export function appendMac(json: Uint8Array, auth: MessageAuthenticator): Uint8Array {
  const bytes = new Uint8Array(json.length + MAC_SUFFIX_LENGTH);
  bytes.set(json, 0);
  writeMac(bytes, json.length, auth);
  return bytes;
}

/**
 * Writes `#` and the MAC of `bytes[0, jsonLength)` right after those bytes, in place (`bytes`
 * must have room for {@link MAC_SUFFIX_LENGTH} more); returns the signed message's length.
 */
export function writeMac(
  bytes: Uint8Array,
  jsonLength: number,
  auth: MessageAuthenticator,
): number {
  const mac = auth.mac(bytes.subarray(0, jsonLength));
  bytes[jsonLength] = HASH;
  // the MAC is hex digits: one byte each
  for (let i = 0; i < mac.length; i++) bytes[jsonLength + 1 + i] = mac.charCodeAt(i);
  return jsonLength + 1 + mac.length;
}

/** Whether `text` is 32 lowercase hex digits, as a MAC is written. */
function isMacText(text: string): boolean {
  if (text.length !== MAC_HEX_DIGITS) return false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (!((c >= 0x30 && c <= 0x39) || (c >= 0x61 && c <= 0x66))) return false;
  }
  return true;
}

/** The MAC's length in hex digits. */
const MAC_HEX_DIGITS = 32;

/**
 * Builds the authenticator for a pre-shared key given as hex (1..64 bytes). `node:crypto` is
 * loaded here, on first use, so importing the package pulls nothing Node-only into a bundle.
 *
 * MACs are compared with `crypto.timingSafeEqual` from the same module. The authenticator is
 * Node-only already (the HMAC is `createHmac`, synchronous, which the codec needs; WebCrypto's
 * `subtle.verify` is asynchronous), so there is no browser path to keep Node built-ins out of:
 * in a browser `createAuthenticator` rejects, and the package's import graph stays clean.
 */
export async function createAuthenticator(keyHex: string): Promise<MessageAuthenticator> {
  if (!/^([0-9a-fA-F]{2}){1,64}$/.test(keyHex)) {
    throw new HalError('INVALID_PARAMETER', '"key" must be 1..64 bytes written as hex digits', {
      details: { parameter: 'key' },
    });
  }
  const { createHmac, timingSafeEqual } = await import('node:crypto');
  const key = Buffer.from(keyHex, 'hex');
  // the digest as hex text: a digest as bytes is a Buffer (an ArrayBuffer) per message, which
  // costs more than the text
  const digestHex = (json: Uint8Array) => createHmac('sha256', key).update(json).digest('hex');
  // the MACs compared, as bytes; reused: verify is synchronous
  const got = Buffer.alloc(MAC_HEX_DIGITS / 2);
  const want = Buffer.alloc(MAC_HEX_DIGITS / 2);
  return {
    mac: (json) => digestHex(json).slice(0, MAC_HEX_DIGITS),
    verify: (json, received) => {
      // the length and the alphabet of a MAC are public; its digits are compared in constant time
      if (!isMacText(received)) return false;
      got.write(received, 'hex');
      want.write(digestHex(json), 0, want.length, 'hex');
      return timingSafeEqual(got, want);
    },
  };
}
