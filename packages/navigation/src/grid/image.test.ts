import jpeg from 'jpeg-js';
import { describe, expect, it } from 'vitest';
import { gridImageDataUrl, renderGridImage } from './image.js';
import { OccupancyGrid } from './occupancy-grid.js';

describe('renderGridImage', () => {
  it('draws occupied cells black and free cells white, north up', () => {
    const grid = new OccupancyGrid();
    grid.seedFromMap({ arena: { width: 5, height: 5 } });
    grid.setLogOdds(0, 99, 4); // the top-left cell
    const image = renderGridImage(grid, { size: 200, showInflation: false });
    expect(image.width).toBe(200);
    expect(image.height).toBe(200);
    expect(Array.from(image.data.subarray(0, 4))).toEqual([20, 20, 20, 255]);
    const bottom = (199 * 200 + 0) * 4;
    expect(Array.from(image.data.subarray(bottom, bottom + 4))).toEqual([250, 250, 250, 255]);
  });

  it('encodes a JPEG data URL that decodes to the same size', () => {
    const grid = new OccupancyGrid();
    const url = gridImageDataUrl(grid, {
      pose: { x: 0, y: 0, yaw: 0 },
      goal: { x: 1, y: 1 },
      path: [
        { x: 0, y: 0 },
        { x: 1, y: 1 },
      ],
      size: 100,
    });
    expect(url.startsWith('data:image/jpeg;base64,')).toBe(true);
    const bytes = Buffer.from(url.slice('data:image/jpeg;base64,'.length), 'base64');
    const decoded = jpeg.decode(bytes, { useTArray: true });
    expect(decoded.width).toBe(100);
    expect(decoded.height).toBe(100);
  });
});
