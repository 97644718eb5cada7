import { NodeHeap } from './binary-heap.js';
import type { ObstacleMap } from './obstacle-map.js';

const SQRT2 = Math.SQRT2;
/** Slack for comparing f values that are equal but summed in a different order. */
const F_EPSILON = 1e-9;
const OCTILE_DIAGONAL_EXTRA = SQRT2 - 2;
// Neighbours in the order west, east, south, north, south-west, south-east, north-west,
// north-east; NEED[k] is the mask of straight neighbours (bits W=1, E=2, S=4, N=8) that must be
// free for the step (a straight step needs its own cell; a diagonal one both cells beside it).
const DX = Int8Array.from([-1, 1, 0, 0, -1, 1, -1, 1]);
const DY = Int8Array.from([0, 0, -1, 1, -1, -1, 1, 1]);
const NEED = Uint8Array.from([1, 2, 4, 8, 4 | 1, 4 | 2, 8 | 1, 8 | 2]);

/** The octile distance between two cells: the exact cost of the best obstacle-free path. */
function octile(x: number, y: number, gx: number, gy: number): number {
  const dx = x > gx ? x - gx : gx - x;
  const dy = y > gy ? y - gy : gy - y;
  return dx + dy + OCTILE_DIAGONAL_EXTRA * (dx < dy ? dx : dy);
}

/**
 * How a search ended. `found`: `cells` holds a shortest path. The others are answers, not
 * failures of the search: the start or goal lies outside the grid, the robot cannot stand on the
 * start or the goal (an obstacle or too close to one), or no route joins them.
 */
export type GridSearchStatus =
  'found' | 'out-of-bounds' | 'start-blocked' | 'goal-blocked' | 'unreachable';

/** The answer of one A* search on cells. */
export interface GridSearchResult {
  status: GridSearchStatus;
  /** Flat cell indices (`cy * width + cx`) from the start to the goal; empty unless found. */
  cells: number[];
  /** Path cost in cells: 1 per straight step, sqrt(2) per diagonal one (octile). */
  cost: number;
  /** Nodes expanded (closed) by the search. */
  expanded: number;
}

/**
 * A* on an {@link ObstacleMap}: 8-connected, where a diagonal step is allowed only when both cells
 * it passes between are free (no corner cutting past an obstacle), step costs 1 and sqrt(2), the
 * octile distance as heuristic (consistent, so the first path found is a shortest one on this
 * connectivity), and an indexed 4-ary heap (with decrease-key) as the open list.
 *
 * All per-search state lives in typed arrays allocated once per grid and reused: a generation
 * counter marks which entries belong to the current search, so nothing is cleared between
 * searches and nothing is allocated per node.
 */
export class AStarSearch {
  readonly #map: ObstacleMap;
  readonly #g: Float64Array;
  readonly #parent: Int32Array;
  /** Per cell: < generation: untouched this search; = generation: queued; generation+1: closed. */
  readonly #mark: Uint32Array;
  readonly #heap: NodeHeap;
  readonly #offsets: Int32Array;
  readonly #tie: number;
  #generation = 0;

  constructor(map: ObstacleMap) {
    this.#map = map;
    const n = map.width * map.height;
    this.#g = new Float64Array(n);
    this.#parent = new Int32Array(n);
    this.#mark = new Uint32Array(n);
    this.#heap = new NodeHeap(n);
    const w = map.width;
    this.#offsets = Int32Array.from([-1, 1, -w, w, -w - 1, -w + 1, w - 1, w + 1]);
    // The heap key is f - tie * g: between equal f, the node with the larger g (nearer the goal)
    // comes first, which keeps A* from expanding whole plateaus of ties. This is exactly A* with
    // the heuristic scaled by 1 / (1 - tie), so tie must be small enough never to reorder two
    // different f: every f here is a + b sqrt(2) with integers |a|, |b| <= K = cells, two
    // different ones differ by more than 1 / (6K) (sqrt(2) is badly approximable:
    // |q sqrt(2) - p| > 1 / (3q)), and g <= sqrt(2) K; tie = 1 / (12 sqrt(2) K^2) keeps
    // tie * g below half that gap, so the first path found is a shortest one.
    const cells = map.width * map.height;
    this.#tie = 1 / (12 * Math.SQRT2 * cells * cells);
  }

  /** Finds a shortest path from cell (sx, sy) to cell (gx, gy). */
  search(sx: number, sy: number, gx: number, gy: number): GridSearchResult {
    const map = this.#map;
    const w = map.width;
    const h = map.height;
    const none = (status: GridSearchStatus): GridSearchResult => ({
      status,
      cells: [],
      cost: 0,
      expanded: 0,
    });
    const inside = (x: number, y: number) =>
      Number.isInteger(x) && Number.isInteger(y) && x >= 0 && y >= 0 && x < w && y < h;
    if (!inside(sx, sy) || !inside(gx, gy)) return none('out-of-bounds');
    if (map.isBlocked(sx, sy)) return none('start-blocked');
    if (map.isBlocked(gx, gy)) return none('goal-blocked');
    const start = sy * w + sx;
    const goal = gy * w + gx;
    if (start === goal) return { status: 'found', cells: [start], cost: 0, expanded: 0 };

    const gen = this.#nextGeneration();
    const blocked = map.blockedBy;
    const g = this.#g;
    const parent = this.#parent;
    const mark = this.#mark;
    const done = gen + 1;
    const heap = this.#heap;
    heap.clear();

    g[start] = 0;
    parent[start] = -1;
    mark[start] = gen;
    heap.push(start, octile(sx, sy, gx, gy));
    const tie = this.#tie;
    let expanded = 0;
    // Neighbour k: index offset, dx, dy, step cost. The four straight ones come first, so their
    // free flags are known when the diagonals (which need both neighbours free) are tried.
    const offset = this.#offsets;

    // `next`: a node to expand straight away without queueing it. When expanding u discovers a
    // neighbour whose f is no larger than u's (u's f is the smallest on the open list), that
    // neighbour is a valid next pick for A*, so it skips the heap: on open ground most of the
    // route is expanded this way.
    let next = -1;
    while (next !== -1 || heap.size > 0) {
      const u = next !== -1 ? next : heap.pop();
      next = -1;
      mark[u] = done;
      expanded += 1;
      if (u === goal) {
        const cells: number[] = [];
        for (let c = goal; c !== -1; c = parent[c] as number) cells.push(c);
        cells.reverse();
        return { status: 'found', cells, cost: g[goal] as number, expanded };
      }
      const ux = u % w;
      const uy = (u - ux) / w;
      const gu = g[u] as number;
      const fu = gu + octile(ux, uy, gx, gy) + F_EPSILON;
      let nextF = 0;
      let nextG = -1;
      // Bit k set: straight neighbour k (west, east, south, north) is on the grid and free.
      let free = 0;
      if (ux > 0 && blocked[u - 1] === 0) free |= 1;
      if (ux < w - 1 && blocked[u + 1] === 0) free |= 2;
      if (uy > 0 && blocked[u - w] === 0) free |= 4;
      if (uy < h - 1 && blocked[u + w] === 0) free |= 8;
      for (let k = 0; k < 8; k += 1) {
        const need = NEED[k] as number;
        if ((free & need) !== need) continue;
        const v = u + (offset[k] as number);
        if (k >= 4 && blocked[v] !== 0) continue;
        const m = mark[v] as number;
        if (m === done) continue;
        const ng = gu + (k < 4 ? 1 : SQRT2);
        if (m < gen) {
          mark[v] = gen;
          g[v] = ng;
          parent[v] = u;
          const fv = ng + octile(ux + (DX[k] as number), uy + (DY[k] as number), gx, gy);
          if (fv <= fu && ng > nextG) {
            // The better candidate for `next`; the previous one goes on the heap.
            if (next !== -1) heap.push(next, nextF - tie * nextG);
            next = v;
            nextF = fv;
            nextG = ng;
          } else {
            heap.push(v, fv - tie * ng);
          }
        } else if (ng < (g[v] as number)) {
          g[v] = ng;
          parent[v] = u;
          const fv = ng + octile(ux + (DX[k] as number), uy + (DY[k] as number), gx, gy);
          if (v === next) {
            nextF = fv;
            nextG = ng;
          } else {
            heap.decrease(v, fv - tie * ng);
          }
        }
      }
    }
    return { status: 'unreachable', cells: [], cost: 0, expanded };
  }

  #nextGeneration(): number {
    // Each search uses two marks (queued, closed); start over before the counter overflows.
    if (this.#generation >= 0xffff_fff0) {
      this.#generation = 0;
      this.#mark.fill(0);
    }
    this.#generation += 2;
    return this.#generation;
  }
}
