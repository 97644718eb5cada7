import { describe, expect, it } from 'vitest';
import { FloorModel } from './floor-model.js';

/** A 40x40 image: `top` above row 20, `bottom` below (RGB). */
function twoTone(top: [number, number, number], bottom: [number, number, number]) {
  const data = new Uint8Array(40 * 40 * 4);
  for (let y = 0; y < 40; y += 1) {
    for (let x = 0; x < 40; x += 1) {
      const c = y < 20 ? top : bottom;
      data.set([...c, 255], (y * 40 + x) * 4);
    }
  }
  return { width: 40, height: 40, data };
}
const at = (x: number, y: number) => (y * 40 + x) * 4;

describe('FloorModel', () => {
  it("learns the floor's look from the bottom of the first frame, the same tone darker too", () => {
    const floor = new FloorModel();
    expect(floor.trained).toBe(false);
    const image = twoTone([92, 107, 128], [214, 208, 196]);
    expect(floor.learn(image)).toBeCloseTo(1, 6);
    expect(floor.trained).toBe(true);
    expect(floor.isFloorAt(image.data, at(5, 35))).toBe(true);
    expect(floor.isFloorAt(image.data, at(5, 5))).toBe(false);
    // The floor's other tile, 14 % darker, same chromaticity.
    expect(floor.isFloorAt(new Uint8Array([184, 178, 166, 255]), 0)).toBe(true);
  });

  it('does not learn an obstacle that fills the bottom of a later frame', () => {
    const floor = new FloorModel();
    floor.learn(twoTone([0, 0, 0], [214, 208, 196]));
    const wall = twoTone([92, 107, 128], [92, 107, 128]);
    expect(floor.learn(wall)).toBe(0);
    expect(floor.isFloorAt(wall.data, at(5, 35))).toBe(false);
  });

  it('skips pixels a label marks as coloured, and refuses bad options', () => {
    const floor = new FloorModel();
    const image = twoTone([0, 0, 0], [214, 40, 40]);
    expect(floor.learn(image, new Uint8Array(40 * 40).fill(1))).toBe(0);
    expect(floor.isFloorAt(image.data, at(5, 35))).toBe(false);
    expect(() => new FloorModel({ memory: 0 })).toThrow(/memory/);
    expect(() => new FloorModel({ referenceHeight: 2 })).toThrow(/referenceHeight/);
  });
});
