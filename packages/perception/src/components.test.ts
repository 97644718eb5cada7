import { describe, expect, it } from 'vitest';
import { findRegions } from './components.js';

/** A label image from rows of characters: '.' background, digits labels. */
function image(rows: string[]) {
  const width = rows[0]?.length ?? 0;
  const labels = new Uint8Array(width * rows.length);
  const rgba = new Uint8Array(width * rows.length * 4);
  rows.forEach((row, y) =>
    [...row].forEach((ch, x) => {
      labels[y * width + x] = ch === '.' ? 0 : Number(ch);
      rgba[(y * width + x) * 4] = ch === '.' ? 0 : 100 + 10 * x;
    }),
  );
  return { labels, width, height: rows.length, rgba };
}

describe('findRegions', () => {
  it('joins 4-connected pixels of one label, a U-shape included, and keeps labels apart', () => {
    const { labels, width, height, rgba } = image([
      '1..1.22',
      '1..1.22',
      '1111...',
      '.......',
      '..1....',
    ]);
    const regions = findRegions(labels, width, height, rgba, 1).sort((a, b) => b.count - a.count);
    expect(regions.map((r) => [r.label, r.count, r.minX, r.maxX, r.minY, r.maxY])).toEqual([
      [1, 8, 0, 3, 0, 2],
      [2, 4, 5, 6, 0, 1],
      [1, 1, 2, 2, 4, 4],
    ]);
    const u = regions[0];
    expect(Array.from(u?.bottom ?? [])).toEqual([2, 2, 2, 2]);
    expect(Array.from(u?.columnCount ?? [])).toEqual([3, 1, 1, 3]);
    expect(u?.columnBrightness[3]).toBe(3 * 130);
  });

  it('leaves out regions smaller than the least size', () => {
    const { labels, width, height, rgba } = image(['11.3', '...3', '2...']);
    expect(
      findRegions(labels, width, height, rgba, 2)
        .map((r) => r.label)
        .sort(),
    ).toEqual([1, 3]);
  });
});
