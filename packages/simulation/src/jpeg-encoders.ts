import type { RgbaImage } from './camera.js';

/*
 * JPEG encoders for camera frames. Each takes an RGBA image and a quality (1..100) and returns
 * the JPEG's bytes. None is imported statically by a browser bundle: jpeg-js loads on first use,
 * sharp is loaded by a specifier no bundler follows and only where Node runs, and the canvas
 * encoder is the browser's own.
 */

/** Encodes an RGBA image as a JPEG of the given quality (1..100). */
export type JpegEncoder = (image: RgbaImage, quality: number) => Promise<Uint8Array>;

/** jpeg-js: pure JavaScript, runs anywhere; the slowest (about 20-50 ms for 320x240). */
export const jpegJsEncoder: JpegEncoder = async (image, quality) => {
  const { default: jpeg } = await import('jpeg-js');
  const encoded = jpeg.encode(
    { width: image.width, height: image.height, data: image.data },
    quality,
  );
  return new Uint8Array(encoded.data);
};

/**
 * The browser's native encoder through `OffscreenCanvas.convertToBlob` (no dependency). Needs
 * OffscreenCanvas (browsers, Web Workers); throws NOT_SUPPORTED-style errors elsewhere.
 */
export const canvasJpegEncoder: JpegEncoder = async (image, quality) => {
  const canvas = new OffscreenCanvas(image.width, image.height);
  const context = canvas.getContext('2d');
  if (context === null) throw new Error('OffscreenCanvas has no 2d context here');
  const pixels = new Uint8ClampedArray(image.width * image.height * 4);
  pixels.set(image.data.subarray(0, pixels.length));
  context.putImageData(new ImageData(pixels, image.width, image.height), 0, 0);
  const blob = await canvas.convertToBlob({ type: 'image/jpeg', quality: quality / 100 });
  return new Uint8Array(await blob.arrayBuffer());
};

/** The part of sharp's API the encoder uses. */
interface SharpLike {
  (
    input: Uint8Array,
    options: { raw: { width: number; height: number; channels: 4 } },
  ): { jpeg(options: { quality: number }): { toBuffer(): Promise<Uint8Array> } };
}

// A variable, so that bundlers do not try to resolve (and pack) a native Node module.
const SHARP_MODULE = 'sharp';

let sharpLoad: Promise<JpegEncoder | undefined> | undefined;

/**
 * sharp (libvips, native; an optional dependency) as a {@link JpegEncoder}: about 1 ms for
 * 320x240. Resolves undefined where Node is not running or sharp is not installed.
 */
export function loadSharpEncoder(): Promise<JpegEncoder | undefined> {
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
    return async (image: RgbaImage, quality: number) =>
      sharp(image.data, { raw: { width: image.width, height: image.height, channels: 4 } })
        .jpeg({ quality })
        .toBuffer();
  })();
  return sharpLoad;
}
