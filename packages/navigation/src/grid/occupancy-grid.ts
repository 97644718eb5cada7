import { GridPlanner } from '../planner/grid-planner.js';
import type { PathPlan, PlanOptions } from '../planner/grid-planner.js';
import { ObstacleMap } from '../planner/obstacle-map.js';
import { checkGridSpec, forEachCellInDisc, worldToCell } from './geometry.js';
import type { GridSpec, Point, Pose2D } from './geometry.js';
import type { KnownMap } from './known-map.js';
import { classifyLogOdds, clampLogOdds, DEFAULT_LOG_ODDS } from './log-odds.js';
import type { CellState, LogOddsModel } from './log-odds.js';
import type { LogOddsGrid } from './log-odds-grid.js';
import { seedGridFromMap } from './map-seeding.js';
import type { SeedOptions } from './map-seeding.js';
import { integrateRayIntoGrid, integrateReadingsIntoGrid } from './range-sensor-update.js';
import type { RangeReadings, RangeSensorModel } from './range-sensor-update.js';

/** Options of an {@link OccupancyGrid}. */
export interface OccupancyGridOptions {
  /** Size along x, metres. Default 5. */
  widthM?: number;
  /** Size along y, metres. Default 5. */
  heightM?: number;
  /** Cell side, metres. Default 0.05. */
  resolutionM?: number;
  /** World x of the grid's lower-left corner, metres. Default -widthM / 2 (centred). */
  originX?: number;
  /** World y of the grid's lower-left corner, metres. Default -heightM / 2 (centred). */
  originY?: number;
  /** The robot's radius, metres: obstacles are inflated by it for planning. Default 0.07. */
  robotRadiusM?: number;
  /** Extra distance kept from obstacles on top of the radius, metres. Default 0.03. */
  clearanceM?: number;
  /** The log-odds sensor model. */
  logOdds?: Partial<LogOddsModel>;
}

/** How many cells are in each state. */
export interface CellCounts {
  unknown: number;
  free: number;
  occupied: number;
}

/**
 * The world model: an occupancy grid of log-odds, updated from the robot's pose and its range
 * sensors by ray casting (free evidence along each ray, occupied evidence where it ends) and
 * seeded from a known map when there is one. It keeps the planner's obstacle layer in step, one
 * cell at a time, so planning on it never rebuilds anything.
 *
 * Unknown cells are planned through (optimistically): the robot finds out on the way.
 */
export class OccupancyGrid implements LogOddsGrid {
  readonly spec: GridSpec;
  /** Log-odds per cell (index `cy * width + cx`); 0 is unknown. Change it through the methods. */
  readonly logOdds: Float32Array;
  /** The planner's obstacle layer (occupied cells, inflated by radius + clearance). */
  readonly obstacles: ObstacleMap;
  readonly planner: GridPlanner;
  readonly model: Readonly<LogOddsModel>;
  readonly robotRadiusM: number;
  readonly clearanceM: number;
  #version = 0;

  constructor(options: OccupancyGridOptions = {}) {
    const widthM = options.widthM ?? 5;
    const heightM = options.heightM ?? 5;
    const resolutionM = options.resolutionM ?? 0.05;
    if (!Number.isFinite(widthM) || widthM <= 0)
      throw new RangeError(`"widthM" must be a positive number, got ${widthM}`);
    if (!Number.isFinite(heightM) || heightM <= 0)
      throw new RangeError(`"heightM" must be a positive number, got ${heightM}`);
    if (!Number.isFinite(resolutionM) || resolutionM <= 0)
      throw new RangeError(`"resolutionM" must be a positive number, got ${resolutionM}`);
    const spec: GridSpec = {
      width: Math.max(1, Math.round(widthM / resolutionM)),
      height: Math.max(1, Math.round(heightM / resolutionM)),
      resolutionM,
      originX: options.originX ?? -widthM / 2,
      originY: options.originY ?? -heightM / 2,
    };
    checkGridSpec(spec);
    this.spec = Object.freeze(spec);
    this.robotRadiusM = options.robotRadiusM ?? 0.07;
    this.clearanceM = options.clearanceM ?? 0.03;
    if (!(this.robotRadiusM >= 0) || !Number.isFinite(this.robotRadiusM))
      throw new RangeError(`"robotRadiusM" must be 0 or more, got ${this.robotRadiusM}`);
    if (!(this.clearanceM >= 0) || !Number.isFinite(this.clearanceM))
      throw new RangeError(`"clearanceM" must be 0 or more, got ${this.clearanceM}`);
    this.model = Object.freeze({ ...DEFAULT_LOG_ODDS, ...options.logOdds });
    this.logOdds = new Float32Array(spec.width * spec.height);
    this.obstacles = new ObstacleMap(
      spec.width,
      spec.height,
      (this.robotRadiusM + this.clearanceM) / resolutionM,
    );
    this.planner = new GridPlanner(this.spec, this.obstacles);
  }

  /**
   * A grid sized to a known map's arena (plus `marginM` on each side, default 0) and seeded from
   * it. Other options as for the constructor.
   */
  static fromMap(
    map: KnownMap,
    options: Omit<OccupancyGridOptions, 'widthM' | 'heightM' | 'originX' | 'originY'> & {
      marginM?: number;
    } = {},
  ): OccupancyGrid {
    const margin = options.marginM ?? 0;
    const width = (map.arena?.width ?? 5) + 2 * margin;
    const height = (map.arena?.height ?? 5) + 2 * margin;
    const { marginM: _margin, ...rest } = options;
    const grid = new OccupancyGrid({ ...rest, widthM: width, heightM: height });
    grid.seedFromMap(map);
    return grid;
  }

  /** Increments on every change of any cell's state (for redrawing and re-planning). */
  get version(): number {
    return this.#version;
  }

  /** The state of cell (cx, cy); outside the grid: unknown. */
  stateOf(cx: number, cy: number): CellState {
    if (cx < 0 || cy < 0 || cx >= this.spec.width || cy >= this.spec.height) return 'unknown';
    return this.#classify(this.logOdds[cy * this.spec.width + cx] as number);
  }

  /** The state of the cell holding world point (x, y); outside the grid: unknown. */
  stateAt(x: number, y: number): CellState {
    const cell = worldToCell(this.spec, x, y);
    return cell === undefined ? 'unknown' : this.stateOf(cell.cx, cell.cy);
  }

  /** Whether the robot's centre may stand at world point (x, y) (not too close to an obstacle). */
  isTraversable(x: number, y: number): boolean {
    const cell = worldToCell(this.spec, x, y);
    return cell !== undefined && !this.obstacles.isBlocked(cell.cx, cell.cy);
  }

  /** Sets a cell's log-odds (clamped), keeping the planner's layer in step. */
  setLogOdds(cx: number, cy: number, value: number): void {
    if (cx < 0 || cy < 0 || cx >= this.spec.width || cy >= this.spec.height) return;
    const i = cy * this.spec.width + cx;
    const before = this.#classify(this.logOdds[i] as number);
    const clamped = clampLogOdds(this.model, value);
    this.logOdds[i] = clamped;
    const after = this.#classify(this.logOdds[i] as number);
    if (before !== after) {
      this.obstacles.setObstacle(cx, cy, after === 'occupied');
      this.#version += 1;
    }
  }

  /** Adds evidence (a log-odds delta) to a cell. */
  addEvidence(cx: number, cy: number, delta: number): void {
    if (cx < 0 || cy < 0 || cx >= this.spec.width || cy >= this.spec.height) return;
    this.setLogOdds(cx, cy, (this.logOdds[cy * this.spec.width + cx] as number) + delta);
  }

  /**
   * Forgets weak obstacles: occupied cells whose log-odds is below `below` (default two hits'
   * worth) become unknown. Cells a known map marked, or that many readings agree on, stay. For
   * recovering when stray readings have closed every route. Returns how many cells it cleared.
   */
  forgetWeakObstacles(below = 2 * this.model.hit): number {
    let cleared = 0;
    for (let i = 0; i < this.logOdds.length; i += 1) {
      const l = this.logOdds[i] as number;
      if (l >= this.model.occupiedAt && l < below) {
        this.setLogOdds(i % this.spec.width, Math.floor(i / this.spec.width), 0);
        cleared += 1;
      }
    }
    return cleared;
  }

  /** Forgets everything: every cell unknown. */
  reset(): void {
    this.logOdds.fill(0);
    this.obstacles.clear();
    this.#version += 1;
  }

  /**
   * Seeds the grid from a known map: cells touching a wall or obstacle become occupied with full
   * confidence (log-odds `occupiedLogOdds`, default the model's max), cells outside the arena
   * too, and (unless `freeSpace` is false) every other cell inside the arena free with low
   * confidence (`freeLogOdds`, default -0.2: one range hit marks an obstacle the map did not show).
   */
  seedFromMap(map: KnownMap, options: SeedOptions = {}): void {
    seedGridFromMap(this, map, options);
  }

  /** Marks the cells under a disc free (the robot's own footprint: it is standing there). */
  markFree(x: number, y: number, radiusM: number): void {
    forEachCellInDisc(this.spec, x, y, radiusM, (cx, cy) => {
      this.addEvidence(cx, cy, this.model.miss);
    });
  }

  /**
   * Lays one range reading into the grid: a ray from (x, y) at `angle` (radians, world frame)
   * that saw an obstacle `rangeM` away (free evidence up to it, occupied evidence in the cell it
   * ends in) or, when `hit` is false, nothing within `rangeM` (free evidence only).
   */
  integrateRay(x: number, y: number, angle: number, rangeM: number, hit: boolean): void {
    integrateRayIntoGrid(this, x, y, angle, rangeM, hit);
  }

  /**
   * Lays the front, left and right (and, when present, front-left and front-right) readings
   * taken at `pose` into the grid. Each sensor adds free evidence across its field of view up to
   * its reading. A reading short of the maximum range adds occupied evidence on the arc of the
   * field of view at that distance: on the whole arc when the grid does not already explain the
   * reading (no occupied cell in the cone at about that distance), else on the arc's unknown
   * cells only. Non-finite readings are ignored.
   */
  integrateRangeReadings(
    pose: Pose2D,
    readings: RangeReadings,
    sensors: Partial<RangeSensorModel> = {},
  ): void {
    integrateReadingsIntoGrid(this, pose, readings, sensors);
  }

  /** How many cells are in each state. */
  counts(): CellCounts {
    const counts: CellCounts = { unknown: 0, free: 0, occupied: 0 };
    for (let i = 0; i < this.logOdds.length; i += 1) {
      counts[this.#classify(this.logOdds[i] as number)] += 1;
    }
    return counts;
  }

  /** Plans a route for the robot's centre between two world points (see {@link GridPlanner}). */
  plan(from: Point, to: Point, options?: PlanOptions): PathPlan {
    return this.planner.plan(from, to, options);
  }

  #classify(l: number): CellState {
    return classifyLogOdds(this.model, l);
  }
}
