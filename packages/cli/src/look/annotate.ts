// The frame `hal look --save` writes: each object boxed in its colour with its label and
// distance, and the free-space boundary drawn as a line across the floor (cyan where something was
// seen, white where the floor is free to the range limit). Drawn into a copy of the RGBA image.
import type { FreeSpaceColumn, RgbaImage, SeenObject } from '@hal/perception';
import { pixelOfPoint } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import { forEachTextPixel, GLYPH_HEIGHT, textWidth } from './pixel-font.js';

type Rgb = readonly [number, number, number];

/** The colour each palette colour's box is drawn in. */
const BOX_COLOURS: Readonly<Record<string, Rgb>> = {
  red: [255, 40, 40],
  orange: [255, 150, 0],
  yellow: [255, 230, 0],
  green: [40, 220, 60],
  blue: [40, 120, 255],
  purple: [190, 70, 255],
};
const OTHER: Rgb = [255, 0, 255];
const BLOCKED_LINE: Rgb = [0, 230, 255];
const FREE_LINE: Rgb = [255, 255, 255];
const LABEL_BACKGROUND: Rgb = [20, 20, 20];

class Canvas {
  constructor(readonly image: RgbaImage) {}

  set(x: number, y: number, [r, g, b]: Rgb): void {
    const { width, height, data } = this.image;
    const px = Math.round(x);
    const py = Math.round(y);
    if (px < 0 || py < 0 || px >= width || py >= height) return;
    const o = (py * width + px) * 4;
    data[o] = r;
    data[o + 1] = g;
    data[o + 2] = b;
    data[o + 3] = 255;
  }

  fill(left: number, top: number, right: number, bottom: number, colour: Rgb): void {
    for (let y = top; y <= bottom; y += 1)
      for (let x = left; x <= right; x += 1) this.set(x, y, colour);
  }

  /** A line from (x0, y0) to (x1, y1), `thickness` pixels across. */
  line(x0: number, y0: number, x1: number, y1: number, colour: Rgb, thickness = 1): void {
    const steps = Math.max(1, Math.ceil(Math.max(Math.abs(x1 - x0), Math.abs(y1 - y0))));
    const half = Math.floor(thickness / 2);
    for (let i = 0; i <= steps; i += 1) {
      const x = x0 + ((x1 - x0) * i) / steps;
      const y = y0 + ((y1 - y0) * i) / steps;
      for (let d = -half; d < thickness - half; d += 1) {
        this.set(x + d, y, colour);
        this.set(x, y + d, colour);
      }
    }
  }

  rectangle(left: number, top: number, right: number, bottom: number, colour: Rgb): void {
    for (const inset of [0, 1]) {
      const [l, t, r, b] = [left - inset, top - inset, right + inset, bottom + inset];
      this.line(l, t, r, t, colour);
      this.line(r, t, r, b, colour);
      this.line(r, b, l, b, colour);
      this.line(l, b, l, t, colour);
    }
  }

  text(text: string, x: number, y: number, colour: Rgb): void {
    forEachTextPixel(text, x, y, (px, py) => this.set(px, py, colour));
  }
}

/** A box's caption: its label and distance, e.g. `RED BOX 0.82M`. */
export function caption(object: SeenObject): string {
  return `${object.label} ${object.distanceM.toFixed(2)}m`;
}

/**
 * A copy of `image` with `objects` boxed and labelled in their colours and the free-space
 * boundary of `freeSpace` drawn (projected back into the image through `projection`).
 */
export function annotateFrame(
  image: RgbaImage,
  objects: readonly SeenObject[],
  freeSpace: readonly FreeSpaceColumn[],
  projection: CameraProjection,
): RgbaImage {
  const out: RgbaImage = { width: image.width, height: image.height, data: image.data.slice() };
  const canvas = new Canvas(out);
  // the boundary first, so that boxes and labels are drawn over it
  let previous: { u: number; v: number; hit: boolean } | undefined;
  for (const column of freeSpace) {
    const at = pixelOfPoint(projection, { x: column.to.x, y: column.to.y, z: 0 });
    if (at === undefined) {
      previous = undefined;
      continue;
    }
    const point = { u: column.column + 0.5, v: Math.min(out.height - 1, at.v), hit: column.hit };
    const colour = column.hit ? BLOCKED_LINE : FREE_LINE;
    if (previous !== undefined) canvas.line(previous.u, previous.v, point.u, point.v, colour, 2);
    else canvas.line(point.u, point.v, point.u, point.v, colour, 2);
    previous = point;
  }
  for (const object of objects) {
    const colour = BOX_COLOURS[object.colour] ?? OTHER;
    const { left, top, right, bottom } = object.image;
    canvas.rectangle(left, top, right, bottom, colour);
    const text = caption(object);
    const w = textWidth(text);
    const x = Math.max(0, Math.min(out.width - w - 2, left));
    // above the box where there is room, else inside its top
    const y = top - GLYPH_HEIGHT - 4 >= 0 ? top - GLYPH_HEIGHT - 4 : top + 3;
    canvas.fill(x, y, x + w + 1, y + GLYPH_HEIGHT + 1, LABEL_BACKGROUND);
    canvas.text(text, x + 1, y + 1, colour);
  }
  return out;
}
