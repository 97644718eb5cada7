import { decompress as fzstdDecompress } from 'fzstd';

/*
 * The browser build's stand-in for @foxglove/wasm-zstd (vite.config.ts aliases it here), with the
 * same API. That package's Emscripten loader `require`s its .wasm file and copies through Node's
 * Buffer, so it cannot be bundled for a page. This one reads zstd chunks with fzstd (plain
 * JavaScript, no WebAssembly), so the demo opens recordings made by `hal record` or `recordHal`
 * in Node. fzstd only decompresses: the demo writes its own recordings uncompressed.
 */

/** Resolves at once: there is nothing to load. */
export const isLoaded: Promise<boolean> = Promise.resolve(true);

/** Decompresses one zstd frame of `size` bytes. */
export function decompress(buffer: Uint8Array, size: number): Uint8Array {
  const out = fzstdDecompress(buffer);
  if (out.byteLength !== size) {
    throw new Error(
      `a zstd chunk decompressed to ${out.byteLength} bytes, not the ${size} its record says`,
    );
  }
  return out;
}

/** Not available in the browser (fzstd has no compressor): record with compression 'none'. */
export function compress(_buffer: Uint8Array, _level?: number): Uint8Array {
  throw new Error(
    "zstd compression is not available in the browser: record with compression 'none'",
  );
}

/** Not available in the browser, as {@link compress}. */
export function compressBound(_size: number): number {
  throw new Error('zstd compression is not available in the browser');
}
