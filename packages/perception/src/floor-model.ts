import type { RgbaImage } from './image.js';

/*
 * Appearance-based floor detection: the floor's look is learnt from a reference region at the
 * bottom of the image (the floor just ahead of the robot), as a histogram of chromaticity
 * (r/(r+g+b), g/(r+g+b)) and brightness; a pixel is floor when its cell (or a neighbour's) was
 * seen there. The first frame is taken to show open floor; later frames teach only pixels whose
 * chromaticity the model already knows (a new floor tone, brighter or darker), so an obstacle
 * that fills the bottom of the image is not learnt as floor.
 */

const CHROMA_BINS = 64;
const LEVEL_BINS = 16;
const CELLS = CHROMA_BINS * CHROMA_BINS * LEVEL_BINS;

/** Options of a {@link FloorModel}. */
export interface FloorModelOptions {
  /** Height of the reference region, as a fraction of the image height. Default 0.1. */
  referenceHeight?: number;
  /** Width of the reference region, centred, as a fraction of the image width. Default 0.6. */
  referenceWidth?: number;
  /**
   * How much of what was learnt each frame keeps (0..1): 1 never forgets. Default 0.98 (a tone
   * unseen for about a hundred frames fades).
   */
  memory?: number;
}

/** The histogram cell of an RGB colour. */
function cellOf(r: number, g: number, b: number): number {
  const sum = r + g + b + 1;
  const c1 = Math.min(CHROMA_BINS - 1, Math.floor((r / sum) * CHROMA_BINS));
  const c2 = Math.min(CHROMA_BINS - 1, Math.floor((g / sum) * CHROMA_BINS));
  const level = Math.min(LEVEL_BINS - 1, Math.floor((sum / 3 / 256) * LEVEL_BINS));
  return (c1 * CHROMA_BINS + c2) * LEVEL_BINS + level;
}

/** A lookup from an RGB colour quantised to 6 bits a channel to its histogram cell. */
let cellTable: Uint32Array | undefined;
function cells(): Uint32Array {
  if (cellTable !== undefined) return cellTable;
  const table = new Uint32Array(64 * 64 * 64);
  for (let r = 0; r < 64; r += 1) {
    for (let g = 0; g < 64; g += 1) {
      for (let b = 0; b < 64; b += 1) {
        table[(r << 12) | (g << 6) | b] = cellOf(r * 4 + 2, g * 4 + 2, b * 4 + 2);
      }
    }
  }
  cellTable = table;
  return table;
}

/** The floor's learnt appearance. */
export class FloorModel {
  readonly #mass = new Float32Array(CELLS);
  /** Which chromaticities (c1, c2 cells) have been seen on the floor, at any brightness. */
  readonly #chroma = new Uint8Array(CHROMA_BINS * CHROMA_BINS);
  #floor = new Uint8Array(CELLS);
  #learnt = 0;
  readonly #options: Required<FloorModelOptions>;

  constructor(options: FloorModelOptions = {}) {
    this.#options = {
      referenceHeight: options.referenceHeight ?? 0.1,
      referenceWidth: options.referenceWidth ?? 0.6,
      memory: options.memory ?? 0.98,
    };
    const { referenceHeight, referenceWidth, memory } = this.#options;
    for (const [name, value] of Object.entries({ referenceHeight, referenceWidth, memory })) {
      if (!(value > 0 && value <= 1)) {
        throw new RangeError(`"${name}" must be in (0, 1], got ${value}`);
      }
    }
  }

  /** Whether anything has been learnt yet. */
  get trained(): boolean {
    return this.#learnt > 0;
  }

  /** Forgets everything learnt. */
  reset(): void {
    this.#mass.fill(0);
    this.#chroma.fill(0);
    this.#floor.fill(0);
    this.#learnt = 0;
  }

  /**
   * Learns from the reference region of `image`, skipping pixels whose `labels` entry is a
   * palette colour (1..6: the objects perception names are never floor). Returns the fraction of the region's pixels learnt.
   */
  learn(image: RgbaImage, labels?: Uint8Array): number {
    const { width, height, data } = image;
    const rows = Math.max(1, Math.round(height * this.#options.referenceHeight));
    const cols = Math.max(1, Math.round(width * this.#options.referenceWidth));
    const x0 = Math.floor((width - cols) / 2);
    const first = !this.trained;
    const table = cells();
    const decay = this.#options.memory;
    for (let i = 0; i < CELLS; i += 1) this.#mass[i] = (this.#mass[i] ?? 0) * decay;
    let learnt = 0;
    let total = 0;
    for (let y = height - rows; y < height; y += 1) {
      for (let x = x0; x < x0 + cols; x += 1) {
        total += 1;
        const p = y * width + x;
        const label = labels?.[p] ?? 0;
        if (label >= 1 && label <= 6) continue;
        const o = p * 4;
        const cell =
          table[
            (((data[o] ?? 0) >> 2) << 12) |
              (((data[o + 1] ?? 0) >> 2) << 6) |
              ((data[o + 2] ?? 0) >> 2)
          ] ?? 0;
        const chroma = Math.floor(cell / LEVEL_BINS);
        if (!first && this.#chroma[chroma] === 0) continue;
        this.#vote(cell);
        learnt += 1;
      }
    }
    this.#learnt += learnt;
    this.#rebuild();
    return total === 0 ? 0 : learnt / total;
  }

  /** One pixel's vote: its cell and the neighbouring cells (chromaticity +-1, brightness +-2). */
  #vote(cell: number): void {
    const level = cell % LEVEL_BINS;
    const c2 = Math.floor(cell / LEVEL_BINS) % CHROMA_BINS;
    const c1 = Math.floor(cell / LEVEL_BINS / CHROMA_BINS);
    for (let d1 = -1; d1 <= 1; d1 += 1) {
      const a = c1 + d1;
      if (a < 0 || a >= CHROMA_BINS) continue;
      for (let d2 = -1; d2 <= 1; d2 += 1) {
        const b = c2 + d2;
        if (b < 0 || b >= CHROMA_BINS) continue;
        if (d1 === 0 && d2 === 0) this.#chroma[a * CHROMA_BINS + b] = 1;
        for (let dl = -2; dl <= 2; dl += 1) {
          const l = level + dl;
          if (l < 0 || l >= LEVEL_BINS) continue;
          const i = (a * CHROMA_BINS + b) * LEVEL_BINS + l;
          this.#mass[i] = (this.#mass[i] ?? 0) + 1;
        }
      }
    }
  }

  /** Cells with enough mass are floor: at least 1 % of the busiest cell's. */
  #rebuild(): void {
    let peak = 0;
    for (let i = 0; i < CELLS; i += 1) peak = Math.max(peak, this.#mass[i] ?? 0);
    const floor = new Uint8Array(CELLS);
    const threshold = Math.max(0.5, peak * 0.01);
    for (let i = 0; i < CELLS; i += 1) if ((this.#mass[i] ?? 0) >= threshold) floor[i] = 1;
    this.#floor = floor;
  }

  /** Whether the pixel at byte offset `o` of `data` (RGBA) looks like the floor. */
  isFloorAt(data: Uint8Array, o: number): boolean {
    const cell =
      cells()[
        (((data[o] ?? 0) >> 2) << 12) | (((data[o + 1] ?? 0) >> 2) << 6) | ((data[o + 2] ?? 0) >> 2)
      ] ?? 0;
    return this.#floor[cell] === 1;
  }
}
