/** An RGBA image, row-major, 4 bytes per pixel (the simulator's and jpeg-js's layout). */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}

/** Index of the byte of pixel (x, y) in an RGBA image's data. */
export function pixelOffset(image: RgbaImage, x: number, y: number): number {
  return (y * image.width + x) * 4;
}

/** Decodes JPEG bytes to RGBA. */
export type JpegDecoder = (bytes: Uint8Array) => RgbaImage | Promise<RgbaImage>;
