/*
 * Connected regions of equal label in a label image (4-connected), with the statistics object
 * detection needs: pixel count, bounding box, and per column the lowest row of the region and
 * the sum of its pixels' brightness (for telling a flat face from a round one). One labelling
 * pass with union-find, one pass to gather.
 */

/** One connected region of a label image. */
export interface Region {
  /** Its label (1..6: the colour). */
  label: number;
  count: number;
  minX: number;
  maxX: number;
  minY: number;
  maxY: number;
  /** Per column from minX, the lowest row of the region in that column, -1 where it has none. */
  bottom: Int16Array;
  /** Per column from minX, the region's pixels in that column. */
  columnCount: Uint16Array;
  /** Per column from minX, the sum of its pixels' brightness (max of r, g, b). */
  columnBrightness: Float32Array;
}

function find(parent: Int32Array, i: number): number {
  let root = i;
  while ((parent[root] ?? root) !== root) root = parent[root] ?? root;
  // Path compression.
  let node = i;
  while (node !== root) {
    const next = parent[node] ?? root;
    parent[node] = root;
    node = next;
  }
  return root;
}

/**
 * The regions of `labels` (one byte a pixel, 0 = background, labels above `maxLabel` too) of at
 * least `minPixels` pixels; `rgba` gives the brightness.
 */
export function findRegions(
  labels: Uint8Array,
  width: number,
  height: number,
  rgba: Uint8Array,
  minPixels: number,
  maxLabel = 255,
): Region[] {
  const ids = new Int32Array(width * height);
  const parent = new Int32Array(width * height + 1);
  let next = 1;
  for (let y = 0; y < height; y += 1) {
    for (let x = 0; x < width; x += 1) {
      const i = y * width + x;
      const label = labels[i] ?? 0;
      if (label === 0 || label > maxLabel) continue;
      const left = x > 0 && labels[i - 1] === label ? (ids[i - 1] ?? 0) : 0;
      const up = y > 0 && labels[i - width] === label ? (ids[i - width] ?? 0) : 0;
      if (left === 0 && up === 0) {
        parent[next] = next;
        ids[i] = next;
        next += 1;
      } else if (left !== 0 && up !== 0) {
        const a = find(parent, left);
        const b = find(parent, up);
        if (a !== b) parent[Math.max(a, b)] = Math.min(a, b);
        ids[i] = Math.min(a, b);
      } else {
        ids[i] = left !== 0 ? left : up;
      }
    }
  }
  // Resolve every provisional id to its root, and count.
  const counts = new Int32Array(next);
  const roots = new Int32Array(next);
  for (let id = 1; id < next; id += 1) roots[id] = find(parent, id);
  for (let i = 0; i < ids.length; i += 1) {
    const id = ids[i] ?? 0;
    if (id === 0) continue;
    const root = roots[id] ?? 0;
    ids[i] = root;
    counts[root] = (counts[root] ?? 0) + 1;
  }
  // Bounding boxes of the large regions.
  const byRoot = new Map<number, { minX: number; maxX: number; minY: number; maxY: number }>();
  for (let y = 0; y < height; y += 1) {
    for (let x = 0; x < width; x += 1) {
      const root = ids[y * width + x] ?? 0;
      if (root === 0 || (counts[root] ?? 0) < minPixels) continue;
      const box = byRoot.get(root);
      if (box === undefined) byRoot.set(root, { minX: x, maxX: x, minY: y, maxY: y });
      else {
        if (x < box.minX) box.minX = x;
        if (x > box.maxX) box.maxX = x;
        box.maxY = y;
      }
    }
  }
  const regions: Region[] = [];
  for (const [root, box] of byRoot) {
    const span = box.maxX - box.minX + 1;
    const region: Region = {
      label: 0,
      count: counts[root] ?? 0,
      ...box,
      bottom: new Int16Array(span).fill(-1),
      columnCount: new Uint16Array(span),
      columnBrightness: new Float32Array(span),
    };
    for (let y = box.minY; y <= box.maxY; y += 1) {
      for (let x = box.minX; x <= box.maxX; x += 1) {
        const i = y * width + x;
        if (ids[i] !== root) continue;
        region.label = labels[i] ?? 0;
        const c = x - box.minX;
        region.bottom[c] = y;
        region.columnCount[c] = (region.columnCount[c] ?? 0) + 1;
        const o = i * 4;
        region.columnBrightness[c] =
          (region.columnBrightness[c] ?? 0) +
          Math.max(rgba[o] ?? 0, rgba[o + 1] ?? 0, rgba[o + 2] ?? 0);
      }
    }
    regions.push(region);
  }
  return regions;
}
