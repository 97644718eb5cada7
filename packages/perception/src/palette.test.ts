import { describe, expect, it } from 'vitest';
import { colourLabel, colourOf, ColourTable, COLOUR_NAMES } from './palette.js';

const rgb = (hex: string): [number, number, number] => {
  const v = Number.parseInt(hex.slice(1), 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255];
};

describe('the palette', () => {
  it("names the simulator's six object colours, shaded down to half and hazed by 15 %", () => {
    const colours = {
      red: '#d62828',
      orange: '#f77f00',
      yellow: '#f4c430',
      green: '#2a9d3f',
      blue: '#1d4ed8',
      purple: '#7b2cbf',
    };
    for (const [name, hex] of Object.entries(colours)) {
      const [r, g, b] = rgb(hex);
      expect(colourOf(r, g, b)).toBe(name);
      expect(colourOf(r * 0.5, g * 0.5, b * 0.5)).toBe(name);
      const haze = (c: number, f: number) => c + (f - c) * 0.15;
      expect(colourOf(haze(r, 200), haze(g, 210), haze(b, 222))).toBe(name);
    }
  });

  it('names none for the floor, the walls, the sky, a dark grey robot and pale or off-hue colours', () => {
    for (const hex of [
      '#d6d0c4',
      '#b8b2a6',
      '#5c6b80',
      '#8a94a6',
      '#6094d6',
      '#cddef0',
      '#46484e',
    ]) {
      expect(colourOf(...rgb(hex)), hex).toBeUndefined();
    }
    // Between red and orange, pale pink, steel blue, teal.
    for (const hex of ['#e07a5f', '#e5989b', '#3d85c6', '#2a9d8f']) {
      expect(colourOf(...rgb(hex)), hex).toBeUndefined();
    }
  });

  it('gives the same labels from its lookup table as from the rule, at the cells’ centres', () => {
    const table = new ColourTable();
    for (let r = 2; r < 256; r += 20) {
      for (let g = 2; g < 256; g += 20) {
        for (let b = 2; b < 256; b += 20) {
          const q = (c: number) => (c >> 2) * 4 + 2;
          expect(table.label(r, g, b)).toBe(colourLabel(q(r), q(g), q(b)));
        }
      }
    }
    expect(COLOUR_NAMES[table.label(214, 40, 40) - 1]).toBe('red');
  });
});
