import { describe, expect, it } from 'vitest';
import { seededRandom } from '../testing/random.js';
import { AStarSearch } from './astar.js';
import { lineOfSight, simplifyPath } from './line-of-sight.js';
import { ObstacleMap } from './obstacle-map.js';

/** Brute-force Dijkstra (linear scan for the minimum) on the same connectivity and costs. */
function dijkstra(map: ObstacleMap, sx: number, sy: number, gx: number, gy: number): number {
  const { width: w, height: h } = map;
  const dist = new Float64Array(w * h).fill(Infinity);
  const done = new Uint8Array(w * h);
  if (map.isBlocked(sx, sy) || map.isBlocked(gx, gy)) return NaN;
  dist[sy * w + sx] = 0;
  for (;;) {
    let u = -1;
    let best = Infinity;
    for (let i = 0; i < w * h; i += 1) {
      if (done[i] === 0 && (dist[i] as number) < best) {
        best = dist[i] as number;
        u = i;
      }
    }
    if (u === -1) return Infinity;
    if (u === gy * w + gx) return best;
    done[u] = 1;
    const ux = u % w;
    const uy = Math.floor(u / w);
    for (let dy = -1; dy <= 1; dy += 1) {
      for (let dx = -1; dx <= 1; dx += 1) {
        if (dx === 0 && dy === 0) continue;
        const vx = ux + dx;
        const vy = uy + dy;
        if (map.isBlocked(vx, vy)) continue;
        if (dx !== 0 && dy !== 0 && (map.isBlocked(ux + dx, uy) || map.isBlocked(ux, uy + dy)))
          continue;
        const v = vy * w + vx;
        const nd = best + (dx !== 0 && dy !== 0 ? Math.SQRT2 : 1);
        if (nd < (dist[v] as number)) dist[v] = nd;
      }
    }
  }
}

/** Checks that a cell path is connected, avoids blocked cells and never cuts a corner. */
function expectValidPath(map: ObstacleMap, cells: readonly number[]): number {
  const w = map.width;
  let cost = 0;
  for (let k = 0; k < cells.length; k += 1) {
    const c = cells[k] as number;
    const x = c % w;
    const y = Math.floor(c / w);
    expect(map.isBlocked(x, y)).toBe(false);
    if (k === 0) continue;
    const p = cells[k - 1] as number;
    const dx = x - (p % w);
    const dy = y - Math.floor(p / w);
    expect(Math.max(Math.abs(dx), Math.abs(dy))).toBe(1);
    if (dx !== 0 && dy !== 0) {
      expect(map.isBlocked(x - dx, y)).toBe(false);
      expect(map.isBlocked(x, y - dy)).toBe(false);
      cost += Math.SQRT2;
    } else {
      cost += 1;
    }
  }
  return cost;
}

function randomMap(random: () => number, w: number, h: number, density: number, inflation = 0) {
  const map = new ObstacleMap(w, h, inflation);
  for (let y = 0; y < h; y += 1) {
    for (let x = 0; x < w; x += 1) if (random() < density) map.setObstacle(x, y, true);
  }
  return map;
}

function fromStrings(rows: string[], inflation = 0): ObstacleMap {
  // Row 0 of the picture is the top (largest y).
  const h = rows.length;
  const w = (rows[0] as string).length;
  const map = new ObstacleMap(w, h, inflation);
  rows.forEach((row, r) => {
    for (let x = 0; x < w; x += 1) if (row[x] === '#') map.setObstacle(x, h - 1 - r, true);
  });
  return map;
}

describe('AStarSearch', () => {
  describe('#search', () => {
    it('finds paths exactly as short as a brute-force Dijkstra on 300 seeded random grids', () => {
      const random = seededRandom(20261123);
      let found = 0;
      let unreachable = 0;
      for (let trial = 0; trial < 300; trial += 1) {
        const w = 3 + Math.floor(random() * 22);
        const h = 3 + Math.floor(random() * 22);
        const inflation = trial % 3 === 0 ? 0.9 : 0;
        const map = randomMap(random, w, h, random() * 0.4, inflation);
        const sx = Math.floor(random() * w);
        const sy = Math.floor(random() * h);
        const gx = Math.floor(random() * w);
        const gy = Math.floor(random() * h);
        map.setObstacle(sx, sy, false);
        map.setObstacle(gx, gy, false);
        const expected = dijkstra(map, sx, sy, gx, gy);
        const result = new AStarSearch(map).search(sx, sy, gx, gy);
        if (Number.isNaN(expected)) {
          expect(['start-blocked', 'goal-blocked']).toContain(result.status);
        } else if (expected === Infinity) {
          expect(result.status).toBe('unreachable');
          unreachable += 1;
        } else {
          expect(result.status).toBe('found');
          expect(result.cost).toBeCloseTo(expected, 9);
          expect(expectValidPath(map, result.cells)).toBeCloseTo(result.cost, 9);
          expect(result.cells[0]).toBe(sy * w + sx);
          expect(result.cells.at(-1)).toBe(gy * w + gx);
          found += 1;
        }
      }
      // The seeded grids exercise both outcomes.
      expect(found).toBeGreaterThan(100);
      expect(unreachable).toBeGreaterThan(10);
    });

    it('gives the same answers when one instance is reused for many searches', () => {
      const random = seededRandom(7);
      const map = randomMap(random, 40, 40, 0.25);
      const reused = new AStarSearch(map);
      for (let k = 0; k < 50; k += 1) {
        const [sx, sy, gx, gy] = [0, 0, 0, 0].map(() => Math.floor(random() * 40)) as [
          number,
          number,
          number,
          number,
        ];
        const a = reused.search(sx, sy, gx, gy);
        const b = new AStarSearch(map).search(sx, sy, gx, gy);
        expect(a.status).toBe(b.status);
        expect(a.cost).toBeCloseTo(b.cost, 12);
      }
    });

    it('does not squeeze diagonally between two obstacles that touch at a corner', () => {
      // Obstacles at (0,0) and (1,1): the step (0,1) -> (1,0) would pass the corner they share.
      const map = fromStrings(['.#', '#.']);
      const result = new AStarSearch(map).search(0, 1, 1, 0);
      expect(result.status).toBe('unreachable');
    });

    it('does not cut the corner of a single obstacle, going around it instead', () => {
      const map = fromStrings(['..', '#.']);
      // (0,1) -> (1,0) diagonally would clip the obstacle at (0,0).
      const result = new AStarSearch(map).search(0, 1, 1, 0);
      expect(result.status).toBe('found');
      expect(result.cells).toEqual([2, 3, 1]);
      expect(result.cost).toBe(2);
    });

    it('expands only the cells of the route on open ground (ties broken toward the goal)', () => {
      const map = new ObstacleMap(100, 100);
      const diagonal = new AStarSearch(map).search(0, 0, 99, 99);
      expect(diagonal.expanded).toBe(100);
      const slanted = new AStarSearch(map).search(0, 10, 99, 60);
      expect(slanted.cost).toBeCloseTo(49 + 50 * Math.SQRT2, 9);
      expect(slanted.expanded).toBe(slanted.cells.length);
    });

    it('takes diagonal steps in open space', () => {
      const map = new ObstacleMap(5, 5);
      const result = new AStarSearch(map).search(0, 0, 4, 4);
      expect(result.cost).toBeCloseTo(4 * Math.SQRT2, 12);
      expect(result.cells).toHaveLength(5);
    });

    it('reports an unreachable goal behind a wall as unreachable, at once, on a 500x500 grid', () => {
      const map = new ObstacleMap(500, 500);
      for (let y = 0; y < 500; y += 1) map.setObstacle(250, y, true);
      const result = new AStarSearch(map).search(10, 10, 490, 490);
      expect(result.status).toBe('unreachable');
      // It explored the whole left half before answering, rather than giving up on a clock.
      expect(result.expanded).toBe(250 * 500);
    });

    it('reports a blocked start, a blocked goal and cells outside the grid', () => {
      const map = fromStrings(['#..', '...', '..#']);
      const search = new AStarSearch(map);
      expect(search.search(0, 2, 1, 1).status).toBe('start-blocked');
      expect(search.search(1, 1, 2, 0).status).toBe('goal-blocked');
      expect(search.search(-1, 0, 1, 1).status).toBe('out-of-bounds');
      expect(search.search(0, 0, 3, 0).status).toBe('out-of-bounds');
      expect(search.search(0.5, 0, 1, 1).status).toBe('out-of-bounds');
    });

    it('answers a search from a cell to itself, and on a one-cell grid', () => {
      expect(new AStarSearch(new ObstacleMap(1, 1)).search(0, 0, 0, 0)).toEqual({
        status: 'found',
        cells: [0],
        cost: 0,
        expanded: 0,
      });
      const map = new ObstacleMap(1, 1);
      map.setObstacle(0, 0, true);
      expect(new AStarSearch(map).search(0, 0, 0, 0).status).toBe('start-blocked');
    });

    it('sees obstacles added and removed between searches without rebuilding anything', () => {
      const map = new ObstacleMap(10, 3);
      const search = new AStarSearch(map);
      expect(search.search(0, 1, 9, 1).cost).toBe(9);
      for (let y = 0; y < 3; y += 1) map.setObstacle(5, y, true);
      expect(search.search(0, 1, 9, 1).status).toBe('unreachable');
      map.setObstacle(5, 0, false);
      const around = search.search(0, 1, 9, 1);
      expect(around.status).toBe('found');
      expect(around.cost).toBeCloseTo(7 + 2 * Math.SQRT2, 12);
    });
  });
});

describe('ObstacleMap', () => {
  it('blocks the cells where a robot of the inflation radius would touch an obstacle', () => {
    const map = new ObstacleMap(9, 9, 1.6, false);
    map.setObstacle(4, 4, true);
    // Distance from a cell centre to the obstacle square < 1.6 cells.
    expect(map.isBlocked(4, 4)).toBe(true);
    expect(map.isBlocked(6, 4)).toBe(true); // 1.5 cells from the square
    expect(map.isBlocked(6, 5)).toBe(true); // hypot(1.5, 0.5) = 1.58
    expect(map.isBlocked(6, 6)).toBe(false); // hypot(1.5, 1.5) = 2.12
    expect(map.isBlocked(7, 4)).toBe(false); // 2.5 cells
    expect(map.isObstacle(6, 4)).toBe(false);
  });

  it('blocks the cells within the inflation radius of the grid edge, unless told not to', () => {
    const walled = new ObstacleMap(10, 6, 2);
    expect(walled.isBlocked(1, 3)).toBe(true); // centre 1.5 cells from the edge
    expect(walled.isBlocked(2, 3)).toBe(false);
    expect(walled.isBlocked(8, 3)).toBe(true);
    expect(walled.isBlocked(5, 4)).toBe(true);
    expect(walled.isBlocked(5, 3)).toBe(false);
    const open = new ObstacleMap(10, 6, 2, false);
    expect(open.isBlocked(0, 0)).toBe(false);
    walled.clear();
    expect(walled.isBlocked(0, 3)).toBe(true);
  });

  it('keeps the inflated layer equal to a fresh build through random marks and clears', () => {
    const random = seededRandom(99);
    const map = new ObstacleMap(30, 20, 2.3);
    for (let k = 0; k < 2000; k += 1) {
      map.setObstacle(Math.floor(random() * 30), Math.floor(random() * 20), random() < 0.6);
    }
    const fresh = new ObstacleMap(30, 20, 2.3);
    for (let i = 0; i < map.obstacle.length; i += 1) {
      if (map.obstacle[i] === 1) fresh.setObstacle(i % 30, Math.floor(i / 30), true);
    }
    expect(Array.from(map.blockedBy)).toEqual(Array.from(fresh.blockedBy));
    map.setInflation(1);
    fresh.setInflation(1);
    expect(Array.from(map.blockedBy)).toEqual(Array.from(fresh.blockedBy));
  });

  it('refuses sizes and radii out of range, naming the argument', () => {
    expect(() => new ObstacleMap(0, 5)).toThrow('"width"');
    expect(() => new ObstacleMap(5, 5, -1)).toThrow('"inflationCells"');
  });

  it('finds the nearest free cell around a blocked one', () => {
    const map = new ObstacleMap(9, 9, 1);
    map.setObstacle(4, 4, true);
    const free = map.nearestFree(4, 4, 5);
    expect(free).toBeDefined();
    // Radius 1 blocks the 3x3 block around the obstacle; the nearest free cells are 2 away.
    expect(Math.hypot((free?.cx ?? 0) - 4, (free?.cy ?? 0) - 4)).toBe(2);
    expect(map.nearestFree(4, 4, 1)).toBeUndefined();
  });
});

describe('simplifyPath', () => {
  it('keeps every segment in line of sight and never makes the path longer', () => {
    const random = seededRandom(4242);
    for (let trial = 0; trial < 60; trial += 1) {
      const map = randomMap(random, 30, 30, 0.2, trial % 2 === 0 ? 1 : 0);
      map.setObstacle(0, 0, false);
      map.setObstacle(29, 29, false);
      const result = new AStarSearch(map).search(0, 0, 29, 29);
      if (result.status !== 'found') continue;
      const simple = simplifyPath(map, result.cells);
      expect(simple[0]).toBe(result.cells[0]);
      expect(simple.at(-1)).toBe(result.cells.at(-1));
      let length = 0;
      for (let k = 1; k < simple.length; k += 1) {
        const a = simple[k - 1] as number;
        const b = simple[k] as number;
        expect(lineOfSight(map, a % 30, Math.floor(a / 30), b % 30, Math.floor(b / 30))).toBe(true);
        length += Math.hypot((b % 30) - (a % 30), Math.floor(b / 30) - Math.floor(a / 30));
      }
      expect(length).toBeLessThanOrEqual(result.cost + 1e-9);
    }
  });

  it('reduces a straight corridor to its two ends', () => {
    const map = new ObstacleMap(20, 1);
    const cells = Array.from({ length: 20 }, (_, i) => i);
    expect(simplifyPath(map, cells)).toEqual([0, 19]);
  });
});

describe('lineOfSight', () => {
  it('is blocked by a line passing exactly between two diagonally touching obstacles', () => {
    const map = fromStrings(['...', '.#.', '#..']);
    // (0,1)..(2,3)? Use the segment (1,0) -> (0,1) through the corner of (0,0) and (1,1).
    expect(lineOfSight(map, 1, 0, 0, 1)).toBe(false);
    expect(lineOfSight(map, 0, 2, 2, 2)).toBe(true);
  });

  it('is blocked by an obstacle the segment crosses, and clear otherwise', () => {
    const map = fromStrings(['.....', '..#..', '.....']);
    expect(lineOfSight(map, 0, 1, 4, 1)).toBe(false);
    expect(lineOfSight(map, 0, 0, 4, 0)).toBe(true);
    expect(lineOfSight(map, 0, 0, 4, 2)).toBe(false);
  });
});
