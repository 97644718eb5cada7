/*
 * The colours perception names: the six the simulator's task objects come in, each as a hue and
 * how far from it a pixel may be. A pixel is of a colour when it is saturated and bright enough
 * (shading darkens a colour without changing its hue or saturation; haze lowers saturation) and
 * its hue is within the colour's band. Grey walls, the floor and pale colours are none.
 */

/**
 * The label of a pixel saturated and bright enough to be coloured, but of no palette colour's hue
 * (a terracotta box, a teal wall): not an object of the palette, and a sign that palette-coloured
 * pixels next to it are the edge of such a thing.
 */
export const OFF_PALETTE = 7;

/** The colours perception names, in the order of their labels (label = index + 1). */
export const COLOUR_NAMES = ['red', 'orange', 'yellow', 'green', 'blue', 'purple'] as const;
export type ColourName = (typeof COLOUR_NAMES)[number];

/** One colour of the palette: its hue and the band around it, degrees. */
export interface PaletteColour {
  name: ColourName;
  hueDeg: number;
  toleranceDeg: number;
}

/** The simulator's six object colours (red #d62828, orange #f77f00, yellow #f4c430, ...). */
export const DEFAULT_PALETTE: readonly PaletteColour[] = Object.freeze([
  { name: 'red', hueDeg: 0, toleranceDeg: 10 },
  { name: 'orange', hueDeg: 31, toleranceDeg: 7 },
  { name: 'yellow', hueDeg: 45, toleranceDeg: 7 },
  { name: 'green', hueDeg: 131, toleranceDeg: 16 },
  { name: 'blue', hueDeg: 224, toleranceDeg: 9 },
  { name: 'purple', hueDeg: 272, toleranceDeg: 10 },
]);

/** Thresholds of colour classification. */
export interface ColourThresholds {
  /** Least saturation (HSV, 0..1) of a coloured pixel. Default 0.45. */
  minSaturation: number;
  /** Least value (HSV brightness, 0..1) of a coloured pixel. Default 0.12. */
  minValue: number;
}

export const DEFAULT_COLOUR_THRESHOLDS: Readonly<ColourThresholds> = Object.freeze({
  minSaturation: 0.45,
  minValue: 0.12,
});

/**
 * The label (1..6, the index in {@link COLOUR_NAMES} + 1) of an RGB colour (0..255 each), 0 when
 * it is not coloured (grey, dark, pale), or {@link OFF_PALETTE} when it is coloured but of no
 * palette colour's hue.
 */
export function colourLabel(
  r: number,
  g: number,
  b: number,
  palette: readonly PaletteColour[] = DEFAULT_PALETTE,
  thresholds: ColourThresholds = DEFAULT_COLOUR_THRESHOLDS,
): number {
  const max = Math.max(r, g, b);
  const min = Math.min(r, g, b);
  const chroma = max - min;
  if (max <= 0 || max / 255 < thresholds.minValue || chroma / max < thresholds.minSaturation) {
    return 0;
  }
  let hue: number;
  if (max === r) hue = (60 * (g - b)) / chroma;
  else if (max === g) hue = 60 * (2 + (b - r) / chroma);
  else hue = 60 * (4 + (r - g) / chroma);
  if (hue < 0) hue += 360;
  let best = OFF_PALETTE;
  let bestDistance = Number.POSITIVE_INFINITY;
  for (const colour of palette) {
    const d = Math.abs(((hue - colour.hueDeg + 540) % 360) - 180);
    if (d <= colour.toleranceDeg && d < bestDistance) {
      bestDistance = d;
      best = COLOUR_NAMES.indexOf(colour.name) + 1;
    }
  }
  return best;
}

/** The colour name of an RGB colour, or undefined when it is none of the palette's. */
export function colourOf(
  r: number,
  g: number,
  b: number,
  palette: readonly PaletteColour[] = DEFAULT_PALETTE,
  thresholds: ColourThresholds = DEFAULT_COLOUR_THRESHOLDS,
): ColourName | undefined {
  const label = colourLabel(r, g, b, palette, thresholds);
  return COLOUR_NAMES[label - 1];
}

/**
 * A lookup table from an RGB colour quantised to 6 bits a channel to its label: one read per
 * pixel instead of a hue computation.
 */
export class ColourTable {
  readonly #labels: Uint8Array;

  constructor(
    palette: readonly PaletteColour[] = DEFAULT_PALETTE,
    thresholds: ColourThresholds = DEFAULT_COLOUR_THRESHOLDS,
  ) {
    this.#labels = new Uint8Array(64 * 64 * 64);
    for (let r = 0; r < 64; r += 1) {
      for (let g = 0; g < 64; g += 1) {
        for (let b = 0; b < 64; b += 1) {
          // The centre of each quantisation cell.
          this.#labels[(r << 12) | (g << 6) | b] = colourLabel(
            r * 4 + 2,
            g * 4 + 2,
            b * 4 + 2,
            palette,
            thresholds,
          );
        }
      }
    }
  }

  /** The label (0 none, 1..6 a palette colour, {@link OFF_PALETTE}) of an RGB colour. */
  label(r: number, g: number, b: number): number {
    return this.#labels[((r >> 2) << 12) | ((g >> 2) << 6) | (b >> 2)] ?? 0;
  }

  /** Labels every pixel of an RGBA image into `out` (one byte a pixel). */
  labelImage(data: Uint8Array, out: Uint8Array): void {
    const table = this.#labels;
    for (let i = 0, o = 0; o < out.length; i += 4, o += 1) {
      out[o] =
        table[
          (((data[i] ?? 0) >> 2) << 12) |
            (((data[i + 1] ?? 0) >> 2) << 6) |
            ((data[i + 2] ?? 0) >> 2)
        ] ?? 0;
    }
  }
}

let shared: ColourTable | undefined;

/** The table of the default palette and thresholds, built once. */
export function defaultColourTable(): ColourTable {
  shared ??= new ColourTable();
  return shared;
}
