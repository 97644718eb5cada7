// The navigation planner's A* against the `pathfinding` package's AStarFinder (diagonal moves only
// when neither cell beside the step is blocked: the same connectivity) on the same grids in one
// run. Both must return paths of the same octile length; the table gives the median time of one
// search. Our planner keeps its obstacle layer across searches (that is how it is used); the
// library needs a fresh grid per search, so its grid.clone() is done outside the timed part.
import { AStarSearch, ObstacleMap } from '@hal/navigation';
import PF from 'pathfinding';
import { reportFigure, reportPoint } from './report/figures.js';

function seededRandom(seed: number): () => number {
  let state = seed >>> 0;
  return () => {
    state = (state + 0x6d2b79f5) >>> 0;
    let t = state;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4_294_967_296;
  };
}

interface Case {
  name: string;
  /** blocked[y][x] = 1 for an obstacle. */
  blocked: number[][];
  start: [number, number];
  goal: [number, number];
  /** Set on the grids of the size series, plotted as time against grid cells. */
  plot?: { kind: string; cells: number };
}

function emptyGrid(size: number): number[][] {
  return Array.from({ length: size }, () => new Array<number>(size).fill(0));
}

function randomGrid(size: number, density: number, seed: number): number[][] {
  const random = seededRandom(seed);
  const grid = emptyGrid(size);
  for (const row of grid) for (let x = 0; x < size; x += 1) row[x] = random() < density ? 1 : 0;
  (grid[0] as number[])[0] = 0;
  (grid[size - 1] as number[])[size - 1] = 0;
  return grid;
}

/**
 * A random grid whose corners are joined: the first seed from `seed` on for which the corners
 * are 4-connected (the connectivity both planners share) through free cells, found by a flood
 * fill, so the benchmark times a search that succeeds.
 */
function connectedRandomGrid(size: number, density: number, seed: number): number[][] {
  for (let s = seed; ; s += 1) {
    const grid = randomGrid(size, density, s);
    const seen = new Uint8Array(size * size);
    const queue = [0];
    seen[0] = 1;
    while (queue.length > 0) {
      const c = queue.pop() as number;
      const x = c % size;
      const y = (c - x) / size;
      for (const [nx, ny] of [
        [x - 1, y],
        [x + 1, y],
        [x, y - 1],
        [x, y + 1],
      ] as const) {
        if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
        const n = ny * size + nx;
        if (seen[n] === 1 || (grid[ny] as number[])[nx] === 1) continue;
        seen[n] = 1;
        queue.push(n);
      }
    }
    if (seen[size * size - 1] === 1) return grid;
  }
}

/** A perfect maze (depth-first backtracker) whose passages are the odd cells. */
function mazeGrid(size: number, seed: number): number[][] {
  const random = seededRandom(seed);
  const grid = Array.from({ length: size }, () => new Array<number>(size).fill(1));
  const rooms = Math.floor((size - 1) / 2);
  const visited = new Uint8Array(rooms * rooms);
  const stack: [number, number][] = [[0, 0]];
  visited[0] = 1;
  (grid[1] as number[])[1] = 0;
  while (stack.length > 0) {
    const [rx, ry] = stack[stack.length - 1] as [number, number];
    const options: [number, number][] = [];
    for (const [dx, dy] of [
      [1, 0],
      [-1, 0],
      [0, 1],
      [0, -1],
    ] as const) {
      const nx = rx + dx;
      const ny = ry + dy;
      if (nx >= 0 && ny >= 0 && nx < rooms && ny < rooms && visited[ny * rooms + nx] === 0)
        options.push([nx, ny]);
    }
    if (options.length === 0) {
      stack.pop();
      continue;
    }
    const [nx, ny] = options[Math.floor(random() * options.length)] as [number, number];
    visited[ny * rooms + nx] = 1;
    (grid[2 * ny + 1] as number[])[2 * nx + 1] = 0;
    (grid[ry + ny + 1] as number[])[rx + nx + 1] = 0;
    stack.push([nx, ny]);
  }
  return grid;
}

function octileLength(path: readonly (readonly number[])[]): number {
  let length = 0;
  for (let k = 1; k < path.length; k += 1) {
    const a = path[k - 1] as readonly number[];
    const b = path[k] as readonly number[];
    length += a[0] !== b[0] && a[1] !== b[1] ? Math.SQRT2 : 1;
  }
  return length;
}

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)] as number;
}

function timeMs(run: () => void): number {
  const start = process.hrtime.bigint();
  run();
  return Number(process.hrtime.bigint() - start) / 1e6;
}

const mazeSize = 200;
const cases: Case[] = [
  { name: '100x100 empty', blocked: emptyGrid(100), start: [0, 0], goal: [99, 99] },
  {
    name: '200x200 20% obstacles',
    blocked: randomGrid(200, 0.2, 2026),
    start: [0, 0],
    goal: [199, 199],
    plot: { kind: 'random 20% obstacles', cells: 200 * 200 },
  },
  // the size series: random 20% obstacles, corner to corner
  ...[300, 400, 500].map((size): Case => ({
    name: `${size}x${size} 20% obstacles (series)`,
    blocked: connectedRandomGrid(size, 0.2, 7 + size),
    start: [0, 0],
    goal: [size - 1, size - 1],
    plot: { kind: 'random 20% obstacles', cells: size * size },
  })),
  {
    name: '200x200 maze',
    blocked: mazeGrid(mazeSize, 11),
    start: [1, 1],
    goal: [mazeSize - 3, mazeSize - 3],
  },
  {
    name: '500x500 30% obstacles',
    blocked: connectedRandomGrid(500, 0.3, 1123),
    start: [0, 0],
    goal: [499, 499],
  },
];

const runs = Number(process.env['ASTAR_BENCH_RUNS'] ?? 15);
const warmupMs = 500;
const measureMs = 1500;
const rows: string[][] = [];
let failures = 0;
let slowest = Infinity;

for (const c of cases) {
  const size = c.blocked.length;
  const width = (c.blocked[0] as number[]).length;
  const map = new ObstacleMap(width, size, 0);
  c.blocked.forEach((row, y) => row.forEach((v, x) => v === 1 && map.setObstacle(x, y, true)));
  const search = new AStarSearch(map);
  const [sx, sy] = c.start;
  const [gx, gy] = c.goal;

  const pfGrid = new PF.Grid(c.blocked);
  const finder = new PF.AStarFinder({ diagonalMovement: PF.DiagonalMovement.OnlyWhenNoObstacles });

  // Warm up both (until the JIT has optimised them), and check they agree.
  let ours = search.search(sx, sy, gx, gy);
  let theirs = finder.findPath(sx, sy, gx, gy, pfGrid.clone());
  const warmUntil = performance.now() + warmupMs;
  for (let k = 0; k < 30 || performance.now() < warmUntil; k += 1) {
    ours = search.search(sx, sy, gx, gy);
    theirs = finder.findPath(sx, sy, gx, gy, pfGrid.clone());
  }
  // The library returns the visited nodes, start and goal included: its step count is
  // length - 1, and its octile length sums the steps.
  const theirLength = theirs.length === 0 ? Infinity : octileLength(theirs);
  const ourLength = ours.status === 'found' ? ours.cost : Infinity;
  const agree = Math.abs(theirLength - ourLength) < 1e-6 || theirLength === ourLength;
  if (!agree || ours.status !== 'found') failures += 1;

  // Alternate the two so that both see the same machine load; at least `runs` runs each.
  const oursMs: number[] = [];
  const theirsMs: number[] = [];
  const measureUntil = performance.now() + measureMs;
  for (let k = 0; k < runs || performance.now() < measureUntil; k += 1) {
    oursMs.push(timeMs(() => search.search(sx, sy, gx, gy)));
    const fresh = pfGrid.clone();
    theirsMs.push(timeMs(() => finder.findPath(sx, sy, gx, gy, fresh)));
  }
  const a = median(oursMs);
  const b = median(theirsMs);
  slowest = Math.min(slowest, b / a);
  reportFigure({
    bench: 'astar',
    name: `A* search, ${c.name} (${ours.status}, same path cost: ${agree ? 'yes' : 'NO'})`,
    value: a,
    unit: 'ms',
    better: 'lower',
    alternative: { name: 'pathfinding AStarFinder', value: b },
    goal: '>= 2x faster, equal path cost',
    met: agree && b / a >= 2,
  });
  if (c.plot !== undefined) {
    for (const [series, value] of [
      ['@hal/navigation AStarSearch', a],
      ['pathfinding AStarFinder', b],
    ] as const) {
      reportPoint({
        plot: 'astar-grid-size',
        title: `A* time by grid size (${c.plot.kind})`,
        series,
        x: c.plot.cells,
        y: value,
        xLabel: 'grid cells',
        yLabel: 'median ms per search',
        logX: true,
        logY: true,
      });
    }
  }
  rows.push([
    c.name,
    ours.status,
    ourLength.toFixed(3),
    theirLength.toFixed(3),
    agree ? 'yes' : 'NO',
    String(ours.expanded),
    a.toFixed(3),
    b.toFixed(3),
    `${(b / a).toFixed(1)}x`,
  ]);
}

const header = [
  'grid',
  'status',
  'ours len',
  'pathfinding len',
  'same',
  'expanded',
  'ours ms',
  'pathfinding ms',
  'speed-up',
];
const widths = header.map((h, i) =>
  Math.max(h.length, ...rows.map((r) => (r[i] as string).length)),
);
const line = (cells: string[]) => cells.map((c, i) => c.padEnd(widths[i] as number)).join('  ');
console.log(
  `A* search, median time of one search (at least ${runs} runs and ${measureMs} ms per grid, ` +
    'after warm-up); 8-connected, no corner cutting',
);
console.log(line(header));
console.log(line(widths.map((w) => '-'.repeat(w))));
for (const row of rows) console.log(line(row));
console.log(`smallest speed-up: ${slowest.toFixed(1)}x (aim: at least 2x)`);
if (failures > 0) {
  console.log(`${failures} grid(s) where the two planners disagreed`);
  process.exit(1);
}
