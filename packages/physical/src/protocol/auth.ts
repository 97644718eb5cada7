import { HalError } from '@hal/types';

/**
 * Message authentication of protocol 1.0, section 8: `<json>#<mac>`, where mac is 32 lowercase hex
 * digits, the first 16 bytes of HMAC-SHA256(key, json bytes).
 */
export interface MessageAuthenticator {
  /** The 32-hex-digit MAC of `json`. */
  mac(json: Uint8Array): string;
}

/** Length of the `#` + 32 hex digits suffix. */
export const MAC_SUFFIX_LENGTH = 33;

/**
 * Builds the authenticator for a pre-shared key given as hex (1..64 bytes). `node:crypto` is
 * loaded here, on first use, so importing the package pulls nothing Node-only into a bundle.
 */
export async function createAuthenticator(keyHex: string): Promise<MessageAuthenticator> {
  if (!/^([0-9a-fA-F]{2}){1,64}$/.test(keyHex)) {
    throw new HalError('INVALID_PARAMETER', '"key" must be 1..64 bytes written as hex digits', {
      details: { parameter: 'key' },
    });
  }
  const { createHmac } = await import('node:crypto');
  const key = Buffer.from(keyHex, 'hex');
  return {
    mac: (json) => createHmac('sha256', key).update(json).digest('hex').slice(0, 32),
  };
}
