import { HalError } from '@hal/types';
import type { RgbaImage } from './camera.js';
import { canvasJpegEncoder, jpegJsEncoder, loadSharpEncoder } from './jpeg-encoders.js';
import type { JpegEncoder } from './jpeg-encoders.js';

/** Base64 of some bytes, in Node and in browsers. */
export function toBase64(bytes: Uint8Array): string {
  const nodeBuffer = (
    globalThis as {
      Buffer?: { from(b: Uint8Array): { toString(encoding: 'base64'): string } };
    }
  ).Buffer;
  if (nodeBuffer !== undefined) return nodeBuffer.from(bytes).toString('base64');
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) {
    text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  }
  return btoa(text);
}

let chosen: Promise<JpegEncoder> | undefined;

/**
 * The fastest JPEG encoder this runtime has, chosen once: in Node, sharp (libvips, native) when
 * it is installed; in a browser, the browser's own encoder (`OffscreenCanvas.convertToBlob`);
 * anywhere else jpeg-js (pure JavaScript).
 */
export function defaultJpegEncoder(): Promise<JpegEncoder> {
  chosen ??= (async () => {
    const sharp = await loadSharpEncoder();
    if (sharp !== undefined) return sharp;
    if (typeof OffscreenCanvas === 'function') return canvasJpegEncoder;
    return jpegJsEncoder;
  })();
  return chosen;
}

/**
 * Encodes an RGBA image as a JPEG (quality 1..100) with `encoder`, by default the fastest this
 * runtime has ({@link defaultJpegEncoder}).
 */
export async function encodeJpeg(
  image: RgbaImage,
  quality = 85,
  encoder?: JpegEncoder,
): Promise<Uint8Array> {
  if (!Number.isInteger(quality) || quality < 1 || quality > 100) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"quality" must be a whole number 1..100, got ${quality}`,
    );
  }
  return (encoder ?? (await defaultJpegEncoder()))(image, quality);
}

/** A `data:image/jpeg;base64,...` URL of a JPEG. */
export function jpegDataUrl(jpegBytes: Uint8Array): string {
  return `data:image/jpeg;base64,${toBase64(jpegBytes)}`;
}
