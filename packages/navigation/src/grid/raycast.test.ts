import { describe, expect, it } from 'vitest';
import { traverseCells } from './raycast.js';

describe('traverseCells', () => {
  it('visits every cell of a diagonal ray in order and stops in the end cell', () => {
    const spec = { width: 10, height: 10, resolutionM: 1, originX: 0, originY: 0 };
    const cells: string[] = [];
    traverseCells(spec, 0.5, 0.5, 3.2, 1.7, (cx, cy) => {
      cells.push(`${cx},${cy}`);
    });
    expect(cells[0]).toBe('0,0');
    expect(cells.at(-1)).toBe('3,1');
    expect(cells).toHaveLength(5);
  });

  it('clips a ray that starts outside the grid', () => {
    const spec = { width: 4, height: 4, resolutionM: 1, originX: 0, originY: 0 };
    const cells: string[] = [];
    traverseCells(spec, -3, 1.5, 2.5, 1.5, (cx, cy) => {
      cells.push(`${cx},${cy}`);
    });
    expect(cells).toEqual(['0,1', '1,1', '2,1']);
    const none: string[] = [];
    traverseCells(spec, -3, -3, -1, -1, (cx, cy) => {
      none.push(`${cx},${cy}`);
    });
    expect(none).toEqual([]);
  });
});
