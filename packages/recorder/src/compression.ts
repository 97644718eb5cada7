import * as zstd from '@foxglove/wasm-zstd';
import type { DecompressHandlers } from '@mcap/core';

/*
 * Chunks are compressed with zstd, one of the two compressions MCAP readers (Foxglove, Lichtblick,
 * the mcap CLI) all understand, through Foxglove's WebAssembly build of it: no native code, so it
 * installs everywhere and runs in a browser too.
 */

/** The chunk compressions a recording can use. */
export type ChunkCompression = 'zstd' | 'none';

/** Resolves once the zstd WebAssembly module is ready (it loads asynchronously). */
export async function zstdReady(): Promise<void> {
  await zstd.isLoaded;
}

/** The writer's `compressChunk` for a compression; call {@link zstdReady} first for zstd. */
export function chunkCompressor(
  compression: ChunkCompression,
): ((data: Uint8Array) => { compression: string; compressedData: Uint8Array }) | undefined {
  if (compression === 'none') return undefined;
  return (data) => ({ compression: 'zstd', compressedData: zstd.compress(data, 3) });
}

/** The reader's decompress handlers (call {@link zstdReady} first). */
export const DECOMPRESS_HANDLERS: DecompressHandlers = {
  zstd: (buffer, decompressedSize) => zstd.decompress(buffer, Number(decompressedSize)),
};
