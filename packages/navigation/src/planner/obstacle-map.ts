/**
 * The planner's view of the world: which cells hold an obstacle, and which are too close to one
 * for the robot's centre (the obstacles inflated by the robot's radius). Both layers are kept up
 * to date incrementally: marking or clearing one obstacle cell touches only the disc of cells
 * around it, so the planner never rebuilds the whole grid before a search.
 *
 * A cell is blocked when a disc of the inflation radius centred on the cell's centre overlaps an
 * obstacle cell (the nearest point of the obstacle's square is closer than the radius): the robot
 * standing there would touch it. Cells outside the grid count as blocked, and so, by default, do
 * the cells within the inflation radius of the grid's edge (as if a wall ran round the grid):
 * the robot's body must stay on the map, not only its centre.
 */
export class ObstacleMap {
  /** Cells along x. */
  readonly width: number;
  /** Cells along y. */
  readonly height: number;
  /** 1 where a cell holds an obstacle. Read-only for callers: change it with `setObstacle`. */
  readonly obstacle: Uint8Array;
  /** How many obstacle cells lie within the inflation radius of each cell (0: free to stand). */
  readonly blockedBy: Uint16Array;
  #radius = 0;
  #offsets: Int32Array = new Int32Array([0, 0]);
  #version = 0;
  readonly #wallAround: boolean;

  /**
   * @param width - cells along x, 1..10000
   * @param height - cells along y, 1..10000
   * @param inflationCells - inflation radius in cells (the robot's radius over the cell size),
   *   0..100; 0 blocks only the obstacle cells themselves
   * @param wallAround - treat the outside of the grid as an obstacle for inflation. Default true.
   */
  constructor(width: number, height: number, inflationCells = 0, wallAround = true) {
    if (!Number.isInteger(width) || width < 1 || width > 10_000)
      throw new RangeError(`"width" must be an integer from 1 to 10000, got ${width}`);
    if (!Number.isInteger(height) || height < 1 || height > 10_000)
      throw new RangeError(`"height" must be an integer from 1 to 10000, got ${height}`);
    this.width = width;
    this.height = height;
    this.obstacle = new Uint8Array(width * height);
    this.blockedBy = new Uint16Array(width * height);
    this.#wallAround = wallAround;
    this.setInflation(inflationCells);
  }

  /** The inflation radius, cells. */
  get inflationCells(): number {
    return this.#radius;
  }

  /** Increments whenever any cell's blocked state may have changed (for cached paths). */
  get version(): number {
    return this.#version;
  }

  /**
   * Changes the inflation radius. This is the one operation that recomputes the whole inflated
   * layer; it is meant for configuration, not for every search.
   */
  setInflation(inflationCells: number): void {
    if (!Number.isFinite(inflationCells) || inflationCells < 0 || inflationCells > 100)
      throw new RangeError(`"inflationCells" must be from 0 to 100, got ${inflationCells}`);
    const r = inflationCells;
    const reach = Math.ceil(r + 0.5);
    const offsets: number[] = [];
    for (let dy = -reach; dy <= reach; dy += 1) {
      for (let dx = -reach; dx <= reach; dx += 1) {
        // Squared distance from this cell's centre to the nearest point of the obstacle's square.
        const ex = Math.max(Math.abs(dx) - 0.5, 0);
        const ey = Math.max(Math.abs(dy) - 0.5, 0);
        if ((dx === 0 && dy === 0) || ex * ex + ey * ey < r * r - 1e-9) offsets.push(dx, dy);
      }
    }
    this.#radius = r;
    this.#offsets = Int32Array.from(offsets);
    this.#resetInflated();
    for (let i = 0; i < this.obstacle.length; i += 1) {
      if (this.obstacle[i] === 1) this.#stamp(i % this.width, Math.floor(i / this.width), 1);
    }
    this.#version += 1;
  }

  /** Marks (true) or clears (false) an obstacle at cell (cx, cy); returns whether it changed. */
  setObstacle(cx: number, cy: number, occupied: boolean): boolean {
    if (cx < 0 || cy < 0 || cx >= this.width || cy >= this.height) return false;
    const i = cy * this.width + cx;
    const now = occupied ? 1 : 0;
    if (this.obstacle[i] === now) return false;
    this.obstacle[i] = now;
    this.#stamp(cx, cy, occupied ? 1 : -1);
    this.#version += 1;
    return true;
  }

  /** Clears every obstacle. */
  clear(): void {
    this.obstacle.fill(0);
    this.#resetInflated();
    this.#version += 1;
  }

  /** Whether the robot's centre may not stand in cell (cx, cy) (outside the grid: blocked). */
  isBlocked(cx: number, cy: number): boolean {
    if (cx < 0 || cy < 0 || cx >= this.width || cy >= this.height) return true;
    return this.blockedBy[cy * this.width + cx] !== 0;
  }

  /** Whether cell (cx, cy) itself holds an obstacle. */
  isObstacle(cx: number, cy: number): boolean {
    if (cx < 0 || cy < 0 || cx >= this.width || cy >= this.height) return false;
    return this.obstacle[cy * this.width + cx] === 1;
  }

  /**
   * The free cell nearest to (cx, cy) by Euclidean distance within `maxRadius` cells, or
   * undefined when there is none. (cx, cy) itself is returned when it is free.
   */
  nearestFree(cx: number, cy: number, maxRadius: number): { cx: number; cy: number } | undefined {
    let best: { cx: number; cy: number } | undefined;
    let bestD = Infinity;
    const reach = Math.ceil(maxRadius);
    for (let ring = 0; ring <= reach; ring += 1) {
      // Every cell of this square ring is at least `ring` away: stop once nothing can beat best.
      if (ring > Math.sqrt(bestD)) break;
      for (let dy = -ring; dy <= ring; dy += 1) {
        const step = dy === -ring || dy === ring ? 1 : 2 * ring;
        for (let dx = -ring; dx <= ring; dx += step === 0 ? 1 : step) {
          const d = dx * dx + dy * dy;
          if (d > maxRadius * maxRadius || d >= bestD) continue;
          if (!this.isBlocked(cx + dx, cy + dy)) {
            best = { cx: cx + dx, cy: cy + dy };
            bestD = d;
          }
        }
      }
    }
    return best;
  }

  /** Zeroes the inflated layer, then blocks the cells too near the grid's edge. */
  #resetInflated(): void {
    this.blockedBy.fill(0);
    if (!this.#wallAround) return;
    // A virtual obstacle just outside the edge is (index + 0.5) cells from a cell's centre.
    const near = (index: number, size: number) =>
      index + 0.5 < this.#radius - 1e-9 || size - index - 0.5 < this.#radius - 1e-9;
    for (let cy = 0; cy < this.height; cy += 1) {
      for (let cx = 0; cx < this.width; cx += 1) {
        if (near(cx, this.width) || near(cy, this.height)) {
          const i = cy * this.width + cx;
          this.blockedBy[i] = (this.blockedBy[i] as number) + 1;
        }
      }
    }
  }

  #stamp(cx: number, cy: number, delta: 1 | -1): void {
    const offsets = this.#offsets;
    const w = this.width;
    const h = this.height;
    const layer = this.blockedBy;
    for (let k = 0; k < offsets.length; k += 2) {
      const x = cx + (offsets[k] as number);
      const y = cy + (offsets[k + 1] as number);
      if (x < 0 || y < 0 || x >= w || y >= h) continue;
      const i = y * w + x;
      layer[i] = (layer[i] as number) + delta;
    }
  }
}
