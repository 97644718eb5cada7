import { HalError, errorMessage } from '@hal/types';
import jpeg from 'jpeg-js';
import type { JpegDecoder, RgbaImage } from './image.js';
import { loadSharpDecoder } from './sharp-decoder.js';

const DATA_URL = /^data:image\/jpeg;base64,/;

/** The bytes of a frame: a `data:image/jpeg;base64,...` URL, bare base64, or bytes. */
export function frameBytes(frame: string | Uint8Array): Uint8Array {
  if (typeof frame !== 'string') return frame;
  const base64 = frame.replace(DATA_URL, '');
  if (!/^[A-Za-z0-9+/]*={0,2}$/.test(base64) || base64.length === 0) {
    throw new HalError(
      'INVALID_PARAMETER',
      'the frame is not a base64 JPEG (nor a data: URL of one)',
    );
  }
  const B = (globalThis as { Buffer?: { from(s: string, e: 'base64'): Uint8Array } }).Buffer;
  if (B !== undefined) return new Uint8Array(B.from(base64, 'base64'));
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i += 1) bytes[i] = text.charCodeAt(i);
  return bytes;
}

/** jpeg-js (pure JavaScript), which runs anywhere. */
export const jpegJsDecoder: JpegDecoder = (bytes) => {
  const image = jpeg.decode(bytes, { useTArray: true, formatAsRGBA: true, maxMemoryUsageInMB: 64 });
  return { width: image.width, height: image.height, data: image.data };
};

let chosen: Promise<JpegDecoder> | undefined;

/** The fastest decoder this runtime has, chosen once: sharp in Node when installed, else jpeg-js. */
export function defaultJpegDecoder(): Promise<JpegDecoder> {
  chosen ??= loadSharpDecoder().then((sharp) => sharp ?? jpegJsDecoder);
  return chosen;
}

/**
 * Decodes a frame to RGBA with `decoder` (default {@link defaultJpegDecoder}), refusing what is not a JPEG with an
 * INVALID_PARAMETER error that says so.
 */
export async function decodeFrame(
  frame: string | Uint8Array,
  decoder?: JpegDecoder,
): Promise<RgbaImage> {
  const bytes = frameBytes(frame);
  const decode = decoder ?? (await defaultJpegDecoder());
  if (bytes.length < 4 || bytes[0] !== 0xff || bytes[1] !== 0xd8) {
    throw new HalError('INVALID_PARAMETER', 'the frame is not a JPEG (no SOI marker)', {
      details: { bytes: bytes.length },
    });
  }
  try {
    return await decode(bytes);
  } catch (error) {
    throw new HalError(
      'INVALID_PARAMETER',
      `the JPEG frame could not be decoded: ${errorMessage(error)}`,
    );
  }
}
