// docs/perception.md's figures against the code they describe, so they cannot drift: the palette
// table against perception's DEFAULT_PALETTE and thresholds (and the simulator's task colours), the
// camera table against V1_CAMERA, the resolution table against the camera's projection.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { COLOURS } from '@hal/eval';
import { cameraProjection, floorPointOfPixel, nearestVisibleFloorM } from '@hal/kinematics';
import { DEFAULT_COLOUR_THRESHOLDS, DEFAULT_PALETTE } from '@hal/perception';
import { V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { section, tableRows } from './doc-graph.js';

const doc = readFileSync(
  fileURLToPath(new URL('../../docs/perception.md', import.meta.url)),
  'utf8',
);
const figures = section(doc, 'What it can and cannot see, in figures');
const projection = cameraProjection(V1_CAMERA);

/** The hue and saturation (HSV) of `#rrggbb`. */
function hueSaturation(hex: string): { hue: number; saturation: number } {
  const [r, g, b] = [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16)) as [
    number,
    number,
    number,
  ];
  const max = Math.max(r, g, b);
  const chroma = max - Math.min(r, g, b);
  let hue =
    max === r
      ? (60 * (g - b)) / chroma
      : max === g
        ? 60 * (2 + (b - r) / chroma)
        : 60 * (4 + (r - g) / chroma);
  if (hue < 0) hue += 360;
  return { hue, saturation: chroma / max };
}

describe('docs/perception.md', () => {
  it("gives the palette's hue bands and thresholds, and the simulator's colours in them", () => {
    const rows = tableRows(figures, [
      'colour',
      'hue band, degrees',
      "simulator's colour",
      'its hue',
      'its saturation',
    ]);
    expect(rows.map((r) => r[0])).toStrictEqual(DEFAULT_PALETTE.map((c) => c.name));
    for (const [name, band, colour, hue, saturation] of rows) {
      const palette = DEFAULT_PALETTE.find((c) => c.name === name)!;
      const low = (palette.hueDeg - palette.toleranceDeg + 360) % 360;
      const high = (palette.hueDeg + palette.toleranceDeg) % 360;
      expect(band, name).toBe(`${low} .. ${high}`);
      expect(colour, name).toBe(`\`${COLOURS[name as keyof typeof COLOURS]}\``);
      const actual = hueSaturation(COLOURS[name as keyof typeof COLOURS]);
      expect(Number(hue), name).toBeCloseTo(actual.hue, -0.5);
      expect(Number(saturation), name).toBeCloseTo(actual.saturation, 2);
    }
    const text = figures.join('\n');
    expect(text).toContain(`saturation at least **${DEFAULT_COLOUR_THRESHOLDS.minSaturation}**`);
    expect(text).toContain(`value at least **${DEFAULT_COLOUR_THRESHOLDS.minValue}**`);
  });

  it("gives V1's camera model", () => {
    const rows = tableRows(section(doc, 'The camera model'), [
      'field',
      'V1 (`V1_CAMERA`)',
      'what it is',
    ]);
    const documented = Object.fromEntries(rows.map((r) => [r[0]!.replace(/`/g, ''), Number(r[1])]));
    expect(documented).toStrictEqual({ ...V1_CAMERA });
  });

  it('gives the floor one image row spans at each distance, as the projection has it', () => {
    const rows = tableRows(figures, [
      'distance',
      'image row',
      'one row spans',
      'the view is this wide',
      'one column spans',
    ]);
    expect(rows.length).toBeGreaterThan(4);
    const distanceOf = (v: number) => {
      const p = floorPointOfPixel(projection, V1_CAMERA.width / 2, v);
      return p === undefined ? Number.POSITIVE_INFINITY : Math.hypot(p.x, p.y);
    };
    for (const [distance, , span, wide] of rows) {
      const d = Number.parseFloat(distance!);
      let v = V1_CAMERA.height;
      while (distanceOf(v) < d - 0.005) v -= 0.01;
      const spanCm = (distanceOf(v - 0.5) - distanceOf(v + 0.5)) * 100;
      expect(Number.parseFloat(span!), `one row at ${d} m`).toBeCloseTo(spanCm, 0);
      const left = floorPointOfPixel(projection, 0, v)!;
      const right = floorPointOfPixel(projection, V1_CAMERA.width, v)!;
      expect(Number.parseFloat(wide!), `the view at ${d} m`).toBeCloseTo(left.y - right.y, 1);
    }
    expect(figures.join('\n')).toContain(
      `the nearest floor it sees is **${nearestVisibleFloorM(projection).toFixed(2)} m**`,
    );
  });
});
