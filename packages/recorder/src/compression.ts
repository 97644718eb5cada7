import type * as Zstd from '@foxglove/wasm-zstd';
import type { DecompressHandlers } from '@mcap/core';

/*
 * Chunks are compressed with zstd, one of the two compressions MCAP readers (Foxglove, Lichtblick,
 * the mcap CLI) all understand, through Foxglove's WebAssembly build of it: no native code, so it
 * installs everywhere and runs in a browser too.
 */

/** The chunk compressions a recording can use. */
export type ChunkCompression = 'zstd' | 'none';

// Loaded on first use, not at import: a program that imports the recorder but records nothing
// (the `hal` command answering --help) does not pay for compiling the WebAssembly module.
let zstd: typeof Zstd | undefined;

/** Loads the zstd WebAssembly module once, and resolves when it is ready. */
export async function zstdReady(): Promise<void> {
  zstd ??= await import('@foxglove/wasm-zstd');
  await zstd.isLoaded;
}

function loadedZstd(): typeof Zstd {
  if (zstd === undefined) throw new Error('zstd is not loaded: await zstdReady() first');
  return zstd;
}

/** The writer's `compressChunk` for a compression; call {@link zstdReady} first for zstd. */
export function chunkCompressor(
  compression: ChunkCompression,
): ((data: Uint8Array) => { compression: string; compressedData: Uint8Array }) | undefined {
  if (compression === 'none') return undefined;
  return (data) => ({ compression: 'zstd', compressedData: loadedZstd().compress(data, 3) });
}

/** The reader's decompress handlers (call {@link zstdReady} first). */
export const DECOMPRESS_HANDLERS: DecompressHandlers = {
  zstd: (buffer, decompressedSize) => loadedZstd().decompress(buffer, Number(decompressedSize)),
};
