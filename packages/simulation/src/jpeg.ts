import type { RgbaImage } from './camera.js';

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

/**
 * Encodes an RGBA image as a JPEG with jpeg-js (pure JavaScript; loaded on first use, so a
 * browser bundle that renders frames another way never runs it).
 */
export async function encodeJpeg(image: RgbaImage, quality = 85): Promise<Uint8Array> {
  const { default: jpeg } = await import('jpeg-js');
  const encoded = jpeg.encode(
    { width: image.width, height: image.height, data: image.data },
    quality,
  );
  return new Uint8Array(encoded.data);
}

/** A `data:image/jpeg;base64,...` URL of a JPEG. */
export function jpegDataUrl(jpegBytes: Uint8Array): string {
  return `data:image/jpeg;base64,${toBase64(jpegBytes)}`;
}
