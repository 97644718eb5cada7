import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { inflateSync } from 'node:zlib';
import jpeg from 'jpeg-js';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { encodePng, imageFormatOf, writeImage } from './image-file.js';

/** A 3x2 image: each pixel a different colour. */
function image() {
  const data = new Uint8Array(3 * 2 * 4);
  for (let i = 0; i < 6; i += 1) data.set([i * 40, 255 - i * 40, (i * 97) % 256, 255], i * 4);
  return { width: 3, height: 2, data };
}

let dir: string;
beforeAll(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-look-image-'));
});
afterAll(async () => {
  await rm(dir, { recursive: true, force: true });
});

describe('encodePng', () => {
  it('writes the signature, a header of the size, and the pixels row by row', () => {
    const png = encodePng(image());
    expect([...png.subarray(0, 8)]).toStrictEqual([137, 80, 78, 71, 13, 10, 26, 10]);
    const view = new DataView(png.buffer, png.byteOffset);
    expect(String.fromCharCode(...png.subarray(12, 16))).toBe('IHDR');
    expect([view.getUint32(16), view.getUint32(20)]).toStrictEqual([3, 2]);
    // IHDR's CRC over its type and data (zlib's crc32 of "IHDR" + data)
    const idatAt = 8 + 12 + 13;
    expect(String.fromCharCode(...png.subarray(idatAt + 4, idatAt + 8))).toBe('IDAT');
    const length = view.getUint32(idatAt);
    const raw = inflateSync(png.subarray(idatAt + 8, idatAt + 8 + length));
    expect(raw.length).toBe(2 * (3 * 4 + 1));
    expect(raw[0]).toBe(0);
    expect([...raw.subarray(1, 13)]).toStrictEqual([...image().data.subarray(0, 12)]);
    expect([...raw.subarray(14, 26)]).toStrictEqual([...image().data.subarray(12, 24)]);
    expect(String.fromCharCode(...png.subarray(png.length - 8, png.length - 4))).toBe('IEND');
    // IEND's CRC is the well-known AE 42 60 82
    expect([...png.subarray(png.length - 4)]).toStrictEqual([0xae, 0x42, 0x60, 0x82]);
  });
});

describe('writeImage', () => {
  it('writes a JPEG or a PNG by the extension', async () => {
    expect(imageFormatOf('a.JPG')).toBe('jpeg');
    expect(imageFormatOf('a.png')).toBe('png');
    expect(imageFormatOf('a.gif')).toBeUndefined();
    const big = { width: 16, height: 8, data: new Uint8Array(16 * 8 * 4).fill(200) };
    await writeImage(join(dir, 'a.jpg'), big);
    const decoded = jpeg.decode(await readFile(join(dir, 'a.jpg')));
    expect([decoded.width, decoded.height]).toStrictEqual([16, 8]);
    await writeImage(join(dir, 'a.png'), big);
    expect([...(await readFile(join(dir, 'a.png'))).subarray(1, 4)]).toStrictEqual([80, 78, 71]);
  });
});
