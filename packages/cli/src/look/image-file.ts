// Writes an RGBA image as a JPEG (the simulator's encoder: sharp where installed, else jpeg-js) or
// a PNG (zlib's deflate, written here: a PNG is a signature and three chunks), by the file's
// extension.
import { writeFile } from 'node:fs/promises';
import { extname } from 'node:path';
import { deflateSync } from 'node:zlib';
import type { RgbaImage } from '@hal/perception';
import { encodeJpeg } from '@hal/simulation';

/** The image formats `--save` writes, by extension. */
export const IMAGE_EXTENSIONS: Readonly<Record<string, 'jpeg' | 'png'>> = {
  '.jpg': 'jpeg',
  '.jpeg': 'jpeg',
  '.png': 'png',
};

/** The format of `path` by its extension, or undefined when it is none `--save` writes. */
export function imageFormatOf(path: string): 'jpeg' | 'png' | undefined {
  return IMAGE_EXTENSIONS[extname(path).toLowerCase()];
}

let crcTable: Uint32Array | undefined;

/** CRC-32 (ISO 3309, as PNG's chunks use). */
function crc32(bytes: Uint8Array): number {
  if (crcTable === undefined) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n += 1) {
      let c = n;
      for (let k = 0; k < 8; k += 1) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let crc = 0xffffffff;
  for (const byte of bytes) crc = (crcTable[(crc ^ byte) & 0xff] ?? 0) ^ (crc >>> 8);
  return (crc ^ 0xffffffff) >>> 0;
}

function chunk(type: string, data: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + data.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, data.length);
  for (let i = 0; i < 4; i += 1) out[4 + i] = type.charCodeAt(i);
  out.set(data, 8);
  view.setUint32(8 + data.length, crc32(out.subarray(4, 8 + data.length)));
  return out;
}

/** An RGBA image as PNG bytes (8 bits a channel, colour type 6, no filtering). */
export function encodePng(image: RgbaImage): Uint8Array {
  const { width, height, data } = image;
  const header = new Uint8Array(13);
  const view = new DataView(header.buffer);
  view.setUint32(0, width);
  view.setUint32(4, height);
  header.set([8, 6, 0, 0, 0], 8);
  const stride = width * 4;
  const raw = new Uint8Array((stride + 1) * height);
  for (let y = 0; y < height; y += 1) {
    raw[y * (stride + 1)] = 0; // filter: none
    raw.set(data.subarray(y * stride, (y + 1) * stride), y * (stride + 1) + 1);
  }
  const parts = [
    new Uint8Array([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', header),
    chunk('IDAT', new Uint8Array(deflateSync(raw))),
    chunk('IEND', new Uint8Array(0)),
  ];
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let at = 0;
  for (const part of parts) {
    out.set(part, at);
    at += part.length;
  }
  return out;
}

/** Writes `image` to `path` as a JPEG or a PNG, by its extension (checked before: see look.ts). */
export async function writeImage(path: string, image: RgbaImage): Promise<void> {
  const bytes = imageFormatOf(path) === 'png' ? encodePng(image) : await encodeJpeg(image, 90);
  await writeFile(path, bytes);
}
