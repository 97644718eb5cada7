import { cameraProjection, floorPointOfPixel } from '@hal/kinematics';
import type { FreeSpaceColumn, SeenObject } from '@hal/perception';
import { V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { annotateFrame, caption } from './annotate.js';
import { forEachTextPixel, GLYPH_HEIGHT, GLYPH_WIDTH, GLYPHS, textWidth } from './pixel-font.js';

const projection = cameraProjection(V1_CAMERA);
const grey = () => ({ width: 320, height: 240, data: new Uint8Array(320 * 240 * 4).fill(128) });
const at = (image: { data: Uint8Array; width: number }, x: number, y: number) => [
  ...image.data.subarray((y * image.width + x) * 4, (y * image.width + x) * 4 + 3),
];

const BLUE_PILLAR: SeenObject = {
  colour: 'blue',
  kind: 'pillar',
  label: 'blue pillar',
  bearingDeg: -20,
  distanceM: 1.32,
  nearDistanceM: 1.2,
  widthM: 0.3,
  heightM: 0.3,
  confidence: 0.9,
  robot: { x: 1.2, y: -0.45 },
  world: { x: 0.7, y: -0.45 },
  image: { left: 200, top: 40, right: 260, bottom: 120 },
  partial: [],
  detector: 'colour',
};

describe('the pixel font', () => {
  it('has 5x7 glyphs for the capitals and digits', () => {
    for (const [char, glyph] of Object.entries(GLYPHS)) {
      expect(glyph, char).toMatch(/^[.#]{35}$/);
    }
    for (const char of 'ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.') expect(GLYPHS[char]).toBeDefined();
  });

  it('lights pixels only inside the text box', () => {
    let lit = 0;
    forEachTextPixel('red box 1.04m', 10, 20, (x, y) => {
      lit += 1;
      expect(x).toBeGreaterThanOrEqual(10);
      expect(x).toBeLessThan(10 + textWidth('red box 1.04m'));
      expect(y).toBeGreaterThanOrEqual(20);
      expect(y).toBeLessThan(20 + GLYPH_HEIGHT);
    });
    expect(lit).toBeGreaterThan(50);
    expect(textWidth('ab')).toBe(2 * GLYPH_WIDTH + 1);
  });
});

describe('annotateFrame', () => {
  it('boxes an object in its colour with its caption above, and leaves the original alone', () => {
    const frame = grey();
    const out = annotateFrame(frame, [BLUE_PILLAR], [], projection);
    expect(at(frame, 200, 80)).toStrictEqual([128, 128, 128]);
    for (const [x, y] of [
      [200, 80],
      [199, 80],
      [260, 100],
      [230, 40],
      [230, 120],
    ] as const) {
      expect(at(out, x, y), `${x},${y}`).toStrictEqual([40, 120, 255]);
    }
    expect(at(out, 230, 80)).toStrictEqual([128, 128, 128]);
    expect(caption(BLUE_PILLAR)).toBe('blue pillar 1.32m');
    // the caption's dark background just above the box
    expect(at(out, 201, 40 - GLYPH_HEIGHT - 4)).toStrictEqual([20, 20, 20]);
  });

  it('draws the free-space boundary where the floor ends: cyan where blocked, white where free', () => {
    const columns: FreeSpaceColumn[] = [100, 102, 104].map((column) => {
      const to = floorPointOfPixel(projection, column + 0.5, 151)!;
      return {
        column,
        bearingRad: Math.atan2(to.y, to.x),
        distanceM: Math.hypot(to.x, to.y),
        hit: column !== 104,
        atEdge: false,
        from: { x: 0.2, y: 0 },
        to,
      };
    });
    const out = annotateFrame(grey(), [], columns, projection);
    expect(at(out, 101, 151)).toStrictEqual([0, 230, 255]);
    expect(at(out, 104, 151)).toStrictEqual([255, 255, 255]);
    expect(at(out, 101, 140)).toStrictEqual([128, 128, 128]);
  });
});
