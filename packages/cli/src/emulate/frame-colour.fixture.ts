// Reads a camera frame (a `data:image/jpeg;base64,` URL or JPEG bytes) for tests: its size, and
// where the red of the eval's red objects (#d62828, shaded) is in it.
import jpeg from 'jpeg-js';

export interface RedRegion {
  width: number;
  height: number;
  /** Red pixels. */
  count: number;
  /** Their mean column, pixels (NaN when there are none). */
  column: number;
}

function bytesOf(frame: string | Uint8Array): Uint8Array {
  if (typeof frame !== 'string') return frame;
  const prefix = 'data:image/jpeg;base64,';
  if (!frame.startsWith(prefix)) throw new Error(`not a JPEG data URL: ${frame.slice(0, 40)}`);
  return Buffer.from(frame.slice(prefix.length), 'base64');
}

/** Decodes `frame` and finds its red pixels (clearly red: r > 110, g and b under half of r). */
export function redRegion(frame: string | Uint8Array): RedRegion {
  const image = jpeg.decode(bytesOf(frame), { useTArray: true });
  let count = 0;
  let columns = 0;
  for (let i = 0; i < image.width * image.height; i += 1) {
    const r = image.data[i * 4]!;
    const g = image.data[i * 4 + 1]!;
    const b = image.data[i * 4 + 2]!;
    if (r > 110 && g * 2 < r && b * 2 < r) {
      count += 1;
      columns += i % image.width;
    }
  }
  return { width: image.width, height: image.height, count, column: columns / count };
}
