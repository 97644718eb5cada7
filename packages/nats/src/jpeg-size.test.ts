import { encodeJpeg } from '@hal/simulation';
import jpeg from 'jpeg-js';
import { describe, expect, it } from 'vitest';
import { jpegSize } from './jpeg-size.js';

describe('jpegSize', () => {
  it('reads the size jpeg-js decodes, from the frame header of an encoded image', () => {
    for (const [width, height] of [
      [320, 240],
      [17, 5],
    ] as const) {
      const data = Buffer.alloc(width * height * 4, 0x80);
      const encoded = jpeg.encode({ data, width, height }, 80).data;
      const decoded = jpeg.decode(encoded);
      expect(jpegSize(encoded)).toEqual({ width: decoded.width, height: decoded.height });
      expect(jpegSize(encoded)).toEqual({ width, height });
    }
  });

  it('says undefined for bytes that are not a JPEG or stop before the frame header', () => {
    expect(jpegSize(new Uint8Array([0x89, 0x50, 0x4e, 0x47]))).toBeUndefined();
    const encoded = jpeg.encode({ data: Buffer.alloc(16 * 16 * 4), width: 16, height: 16 }).data;
    expect(jpegSize(encoded.subarray(0, 20))).toBeUndefined();
  });

  it('reads the frames of the encoder the simulated camera uses (markers before the header)', async () => {
    const width = 64;
    const height = 48;
    const encoded = await encodeJpeg({ data: new Uint8Array(width * height * 4), width, height });
    expect(jpegSize(encoded)).toEqual({ width, height });
  });
});
