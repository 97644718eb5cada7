import type { JpegDecoder } from './image.js';

/** The part of sharp's API the decoder uses. */
interface SharpLike {
  (input: Uint8Array): {
    ensureAlpha(): {
      raw(): {
        toBuffer(options: { resolveWithObject: true }): Promise<{
          data: Uint8Array;
          info: { width: number; height: number; channels: number };
        }>;
      };
    };
  };
}

// A variable, so that bundlers do not try to resolve (and pack) a native Node module.
const SHARP_MODULE = 'sharp';

let sharpLoad: Promise<JpegDecoder | undefined> | undefined;

/**
 * sharp (libvips, native; an optional dependency) as a {@link JpegDecoder}: about 2.4 ms for a
 * 320x240 frame on a 2-core machine against jpeg-js's 3.4 (bench/perception-libs.bench.ts).
 * Resolves undefined where Node is not running or sharp is not installed.
 */
export function loadSharpDecoder(): Promise<JpegDecoder | undefined> {
  sharpLoad ??= (async () => {
    const isNode =
      (globalThis as { process?: { versions?: { node?: string } } }).process?.versions?.node !==
      undefined;
    if (!isNode) return undefined;
    let sharp: SharpLike;
    try {
      const mod = (await import(/* @vite-ignore */ SHARP_MODULE)) as { default: SharpLike };
      sharp = mod.default;
    } catch {
      return undefined;
    }
    return async (bytes: Uint8Array) => {
      const { data, info } = await sharp(bytes)
        .ensureAlpha()
        .raw()
        .toBuffer({ resolveWithObject: true });
      if (info.channels !== 4) throw new Error(`sharp gave ${info.channels} channels, not 4`);
      return {
        width: info.width,
        height: info.height,
        data: new Uint8Array(data.buffer, data.byteOffset, data.length),
      };
    };
  })();
  return sharpLoad;
}
