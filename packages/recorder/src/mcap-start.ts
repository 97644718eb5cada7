import { MCAP_MAGIC } from '@mcap/core';
import { RecordingReadError } from './recording-read-error.js';

/** The first bytes of `bytes` as hex and as text (non-printable shown as '.'), for a message. */
function firstBytes(bytes: Uint8Array): string {
  const head = bytes.subarray(0, 8);
  const hex = Array.from(head, (b) => b.toString(16).padStart(2, '0')).join(' ');
  const text = Array.from(head, (b) => (b >= 0x20 && b < 0x7f ? String.fromCharCode(b) : '.'));
  return `${hex} "${text.join('')}"`;
}

/**
 * Refuses what cannot be an MCAP recording before any reader sees it: an empty file, a file
 * that does not start with MCAP's magic bytes (`\x89MCAP0\r\n`), or one that ends inside them.
 * `name` is how the caller calls the file (its path, its name in a page).
 */
export function checkMcapStart(bytes: Uint8Array, name: string): void {
  if (bytes.byteLength === 0) {
    throw new RecordingReadError('EMPTY', `${name} is empty (0 bytes): not an MCAP recording`, {
      offset: 0,
    });
  }
  const prefix = Math.min(bytes.byteLength, MCAP_MAGIC.length);
  for (let i = 0; i < prefix; i += 1) {
    if (bytes[i] !== MCAP_MAGIC[i]) {
      throw new RecordingReadError(
        'NOT_MCAP',
        `${name} is not an MCAP file: it does not start with MCAP's magic bytes (it starts with ${firstBytes(bytes)})`,
        { offset: 0 },
      );
    }
  }
  if (bytes.byteLength < MCAP_MAGIC.length) {
    throw new RecordingReadError(
      'NO_HEADER',
      `${name} holds no recording: it ends after ${bytes.byteLength} bytes, inside MCAP's magic bytes`,
      { offset: bytes.byteLength },
    );
  }
}
