import { findRegions } from './components.js';
import type { Detector, DetectorInput } from './detector.js';
import { kindFromShading } from './object-kind.js';
import { COLOUR_NAMES, OFF_PALETTE } from './palette.js';
import type { Detection } from './project-object.js';

/**
 * Hides base rows that disagree with their neighbours (a corner of an object blurred into the
 * floor by the JPEG): more than 2 rows from the median of the visible rows within 3 columns.
 * Returns how many it hid.
 */
function dropOutliers(rows: Int16Array): number {
  const original = Int16Array.from(rows);
  let dropped = 0;
  const window: number[] = [];
  for (let c = 0; c < original.length; c += 1) {
    const row = original[c] ?? -1;
    if (row < 0) continue;
    window.length = 0;
    for (let k = Math.max(0, c - 3); k <= Math.min(original.length - 1, c + 3); k += 1) {
      const r = original[k] ?? -1;
      if (r >= 0) window.push(r);
    }
    window.sort((a, b) => a - b);
    const median = window[Math.floor(window.length / 2)] ?? row;
    if (Math.abs(row - median) > 2) {
      rows[c] = -1;
      dropped += 1;
    }
  }
  return dropped;
}

/** The least height of an object, image rows. */
const MIN_ROWS = 4;
/** How far around a region's box off-palette pixels are counted, pixels. */
const AROUND = 3;

/** The off-palette pixels within a region's bounding box grown by {@link AROUND}. */
function offPaletteAround(
  labels: Uint8Array,
  width: number,
  height: number,
  box: { minX: number; maxX: number; minY: number; maxY: number },
): number {
  let count = 0;
  const y1 = Math.min(height - 1, box.maxY + AROUND);
  const x1 = Math.min(width - 1, box.maxX + AROUND);
  for (let y = Math.max(0, box.minY - AROUND); y <= y1; y += 1) {
    for (let x = Math.max(0, box.minX - AROUND); x <= x1; x += 1) {
      if (labels[y * width + x] === OFF_PALETTE) count += 1;
    }
  }
  return count;
}

/** Options of {@link ColourDetector}. */
export interface ColourDetectorOptions {
  /** Smallest region reported, pixels. Default 30. */
  minPixels?: number;
}

/**
 * Colour segmentation: each connected region of one palette colour that stands on the floor is
 * an object. Needs no model. Regions whose base is hidden in every column (behind something
 * nearer) and that do not reach the image's bottom are left out: there is no floor point to
 * place them by.
 */
export class ColourDetector implements Detector {
  readonly name = 'colour';
  readonly #minPixels: number;

  constructor(options: ColourDetectorOptions = {}) {
    this.#minPixels = options.minPixels ?? 30;
    if (!(Number.isInteger(this.#minPixels) && this.#minPixels >= 1)) {
      throw new RangeError(
        `"minPixels" must be a whole number of 1 or more, got ${this.#minPixels}`,
      );
    }
  }

  detect({ image, labels, floor }: DetectorInput): Detection[] {
    const { width, height, data } = image;
    const regions = findRegions(labels, width, height, data, this.#minPixels, COLOUR_NAMES.length);
    const detections: Detection[] = [];
    for (const region of regions) {
      const colour = COLOUR_NAMES[region.label - 1];
      if (colour === undefined) continue;
      // A sliver a row or two tall stands on nothing: the shading along an edge.
      if (region.maxY - region.minY + 1 < MIN_ROWS) continue;
      // Palette-coloured pixels amid more of a colour the palette lacks are the edge of such a
      // thing (a terracotta box's reddest shading), not an object of their own.
      if (offPaletteAround(labels, width, height, region) >= region.count) continue;
      const baseRows = new Int16Array(region.bottom.length).fill(-1);
      let visible = 0;
      for (let c = 0; c < region.bottom.length; c += 1) {
        const row = region.bottom[c] ?? -1;
        if (row < 0 || row >= height - 1) continue;
        // The base shows where the pixel below the region is floor (not an occluder).
        const below = ((row + 1) * width + region.minX + c) * 4;
        if (floor.isFloorAt(data, below) || floor.isFloorAt(data, below + width * 4)) {
          baseRows[c] = row + 1;
          visible += 1;
        }
      }
      visible -= dropOutliers(baseRows);
      const cutAtBottom = region.maxY >= height - 1;
      if (visible === 0 && !cutAtBottom) continue;
      if (visible === 0) baseRows.fill(height);
      const size = Math.min(1, region.count / 600);
      const baseShare = visible / Math.max(1, region.bottom.length);
      const confidence =
        Math.round((0.5 + 0.5 * size) * (cutAtBottom ? 0.8 : 0.7 + 0.3 * baseShare) * 100) / 100;
      detections.push({
        colour,
        kind: kindFromShading(region.columnBrightness, region.columnCount),
        box: { left: region.minX, top: region.minY, right: region.maxX, bottom: region.maxY },
        confidence,
        baseRows,
        detector: this.name,
      });
    }
    return detections;
  }
}
