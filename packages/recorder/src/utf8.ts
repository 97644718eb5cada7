const encoder = new TextEncoder();

/**
 * The UTF-8 bytes of `text`. In Node, `Buffer.from`, which took a fifth of `TextEncoder`'s
 * time for a call record (about 0.2 µs against 1 µs for 240 characters): every record pays it.
 * In a browser, `TextEncoder`.
 */
export const utf8: (text: string) => Uint8Array =
  typeof Buffer === 'function' && typeof Buffer.from === 'function'
    ? (text) => Buffer.from(text, 'utf8')
    : (text) => encoder.encode(text);
