import * as wasmZstd from '@foxglove/wasm-zstd';
import { beforeAll, describe, expect, it } from 'vitest';
import { compress, decompress, isLoaded } from './zstd-browser.js';

function sample(size: number): Uint8Array {
  // JSON-like text: what a recording's chunks hold
  let text = '';
  for (let i = 0; text.length < size; i += 1) text += `{"x":${Math.sin(i).toFixed(6)}},`;
  return new TextEncoder().encode(text.slice(0, size));
}

describe("the browser's zstd stand-in", () => {
  beforeAll(async () => {
    await wasmZstd.isLoaded;
    expect(await isLoaded).toBe(true);
  });

  it("decompresses what Foxglove's WebAssembly zstd compressed, byte for byte", () => {
    for (const size of [1, 1000, 64 * 1024, 300_000]) {
      const original = sample(size);
      expect(original.byteLength).toBe(size);
      const packed = wasmZstd.compress(original, 3);
      expect(packed.byteLength).toBeLessThan(Math.max(original.byteLength, 64));
      const out = decompress(packed, original.byteLength);
      // Buffer's compare, not toEqual: a deep equality of 300 kB takes seconds
      expect(Buffer.from(out).equals(Buffer.from(original))).toBe(true);
    }
  });

  it('fails when a chunk decompresses to another size than its record says', () => {
    const original = sample(1000);
    const packed = wasmZstd.compress(original, 3);
    expect(() => decompress(packed, 1200)).toThrow(/1000 bytes, not the 1200/);
  });

  it('refuses to compress, naming the compression to record with instead', () => {
    expect(() => compress(sample(100))).toThrow(/compression 'none'/);
  });
});
