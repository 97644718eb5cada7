import { GridPlanner } from '../planner/grid-planner.js';
import type { PathPlan, PlanOptions } from '../planner/grid-planner.js';
import { ObstacleMap } from '../planner/obstacle-map.js';
import { cellCentre, checkGridSpec, worldToCell } from './geometry.js';
import type { GridSpec, Point } from './geometry.js';
import { mapSolids } from './known-map.js';
import type { KnownMap } from './known-map.js';
import { traverseCells } from './raycast.js';

/** What the world model believes about one cell. */
export type CellState = 'unknown' | 'free' | 'occupied';

/** A robot pose in the plane: metres, and yaw in radians counter-clockwise from +x (REP-103). */
export interface Pose2D {
  x: number;
  y: number;
  yaw: number;
}

/**
 * The log-odds sensor model. Each observation adds `hit` (the ray ended in the cell) or `miss`
 * (the ray passed through it) to the cell's log-odds, clamped to [min, max]. A cell is occupied
 * at or above `occupiedAt`, free at or below `freeAt`, and unknown between.
 */
export interface LogOddsModel {
  hit: number;
  miss: number;
  min: number;
  max: number;
  occupiedAt: number;
  freeAt: number;
}

/** The default log-odds model: one hit marks a cell occupied, one miss marks it free. */
export const DEFAULT_LOG_ODDS: Readonly<LogOddsModel> = Object.freeze({
  hit: 0.85,
  miss: -0.4,
  min: -4,
  max: 4,
  occupiedAt: 0.6,
  freeAt: -0.15,
});

/** Log-odds of a cell a known map shows free: free, but one range hit makes it occupied. */
const SEEDED_FREE = -0.2;

/** How the robot's range sensors look at the world. */
export interface RangeSensorModel {
  /** Longest reading, metres: a reading at (or above) it means nothing was seen. Default 2. */
  maxRangeM: number;
  /**
   * How far from the robot's centre readings are measured, metres (a reading of 0 means an
   * obstacle this far from the centre). Default 0.07, the V1 cube's body radius.
   */
  originOffsetM: number;
  /** Full field of view of each sensor, degrees: free evidence is laid across it. Default 25. */
  fieldOfViewDeg: number;
  /** Rays per sensor across the field of view for free evidence. Default 5. */
  rays: number;
}

/** The default range sensor model (matches the simulated sensors' defaults). */
export const DEFAULT_RANGE_SENSORS: Readonly<RangeSensorModel> = Object.freeze({
  maxRangeM: 2,
  originOffsetM: 0.07,
  fieldOfViewDeg: 25,
  rays: 5,
});

/** Range readings, metres, as `vision.getDistanceSensors()` returns them. */
export interface RangeReadings {
  front: number;
  left: number;
  right: number;
  frontLeft?: number | undefined;
  frontRight?: number | undefined;
}

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
export class OccupancyGrid {
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
    const clamped = Math.min(this.model.max, Math.max(this.model.min, value));
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
  seedFromMap(
    map: KnownMap,
    options: { freeSpace?: boolean; freeLogOdds?: number; occupiedLogOdds?: number } = {},
  ): void {
    const freeValue = options.freeLogOdds ?? SEEDED_FREE;
    const occupiedValue = options.occupiedLogOdds ?? this.model.max;
    const { width, height, resolutionM: res } = this.spec;
    const solids = mapSolids(map);
    const arena = map.arena;
    for (let cy = 0; cy < height; cy += 1) {
      for (let cx = 0; cx < width; cx += 1) {
        const minX = this.spec.originX + cx * res;
        const minY = this.spec.originY + cy * res;
        const maxX = minX + res;
        const maxY = minY + res;
        let occupied =
          arena !== undefined &&
          (minX < -arena.width / 2 ||
            maxX > arena.width / 2 ||
            minY < -arena.height / 2 ||
            maxY > arena.height / 2);
        for (let k = 0; !occupied && k < solids.length; k += 1) {
          const s = solids[k];
          if (s === undefined) continue;
          if (s.kind === 'rect') {
            occupied = minX < s.maxX && maxX > s.minX && minY < s.maxY && maxY > s.minY;
          } else {
            const nx = Math.min(Math.max(s.x, minX), maxX);
            const ny = Math.min(Math.max(s.y, minY), maxY);
            occupied = (nx - s.x) ** 2 + (ny - s.y) ** 2 < s.radius * s.radius;
          }
        }
        if (occupied) this.setLogOdds(cx, cy, occupiedValue);
        else if (options.freeSpace !== false) this.setLogOdds(cx, cy, freeValue);
      }
    }
  }

  /** Marks the cells under a disc free (the robot's own footprint: it is standing there). */
  markFree(x: number, y: number, radiusM: number): void {
    const res = this.spec.resolutionM;
    const reach = Math.ceil(radiusM / res) + 1;
    const centre = worldToCell(this.spec, x, y);
    if (centre === undefined) return;
    for (let dy = -reach; dy <= reach; dy += 1) {
      for (let dx = -reach; dx <= reach; dx += 1) {
        const c = cellCentre(this.spec, centre.cx + dx, centre.cy + dy);
        if (Math.hypot(c.x - x, c.y - y) <= radiusM) {
          this.addEvidence(centre.cx + dx, centre.cy + dy, this.model.miss);
        }
      }
    }
  }

  /**
   * Lays one range reading into the grid: a ray from (x, y) at `angle` (radians, world frame)
   * that saw an obstacle `rangeM` away (free evidence up to it, occupied evidence in the cell it
   * ends in) or, when `hit` is false, nothing within `rangeM` (free evidence only).
   */
  integrateRay(x: number, y: number, angle: number, rangeM: number, hit: boolean): void {
    if (![x, y, angle, rangeM].every(Number.isFinite) || rangeM < 0) return;
    const ex = x + rangeM * Math.cos(angle);
    const ey = y + rangeM * Math.sin(angle);
    const end = worldToCell(this.spec, ex, ey);
    const endIndex = end === undefined ? -1 : end.cy * this.spec.width + end.cx;
    traverseCells(this.spec, x, y, ex, ey, (cx, cy) => {
      if (cy * this.spec.width + cx === endIndex) return false;
      this.addEvidence(cx, cy, this.model.miss);
      return true;
    });
    if (hit && end !== undefined) this.addEvidence(end.cx, end.cy, this.model.hit);
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
    const model = { ...DEFAULT_RANGE_SENSORS, ...sensors };
    const beams: [number, number | undefined][] = [
      [0, readings.front],
      [Math.PI / 2, readings.left],
      [-Math.PI / 2, readings.right],
      [Math.PI / 4, readings.frontLeft],
      [-Math.PI / 4, readings.frontRight],
    ];
    const fov = (model.fieldOfViewDeg * Math.PI) / 180;
    const rays = Math.max(1, Math.floor(model.rays));
    for (const [offset, reading] of beams) {
      if (reading === undefined || !Number.isFinite(reading) || reading < 0) continue;
      const hit = reading < model.maxRangeM - 1e-6;
      const range = Math.min(reading, model.maxRangeM) + model.originOffsetM;
      const angles: number[] = [];
      for (let i = 0; i < rays; i += 1) {
        angles.push(pose.yaw + offset + (rays === 1 ? 0 : (i / (rays - 1) - 0.5) * fov));
      }
      // What the map already explains: the nearest occupied cell across the cone. A reading
      // that far (or farther) adds no new obstacle; a shorter one means something unexpected.
      const expected = hit
        ? this.#nearestOccupied(pose, angles, range + 4 * this.spec.resolutionM)
        : Infinity;
      const unexpected = hit && range < expected - 2 * this.spec.resolutionM;
      // Free evidence across the cone: nothing in it is nearer than the reading.
      for (const angle of angles) this.integrateRay(pose.x, pose.y, angle, range, false);
      if (!hit) continue;
      // Occupied evidence on the arc at the reading's distance: a cone's reading does not say
      // where across the cone the obstacle is, so the whole arc is suspect (free evidence from
      // other views clears the parts that are not). When the grid already explains the reading,
      // only the arc's unknown cells are marked: they may hide more of the same obstacle (the
      // rest of a wall seen in dashes), while cells known free stay free.
      const arc = new Set<number>();
      const steps = Math.max(1, Math.ceil((range * fov) / (this.spec.resolutionM / 2)));
      for (let k = 0; k <= steps; k += 1) {
        const angle = pose.yaw + offset + (rays === 1 ? 0 : (k / steps - 0.5) * fov);
        const end = worldToCell(
          this.spec,
          pose.x + range * Math.cos(angle),
          pose.y + range * Math.sin(angle),
        );
        if (end === undefined) continue;
        if (!unexpected && this.stateOf(end.cx, end.cy) !== 'unknown') continue;
        arc.add(end.cy * this.spec.width + end.cx);
      }
      for (const index of arc) {
        this.addEvidence(
          index % this.spec.width,
          Math.floor(index / this.spec.width),
          this.model.hit,
        );
      }
    }
  }

  /**
   * Distance to the nearest occupied cell along any of the rays, up to `limit` metres. The edge
   * of the grid counts as a wall (as it does for planning): the arena's walls usually lie there.
   */
  #nearestOccupied(pose: Pose2D, angles: readonly number[], limit: number): number {
    let nearest = Infinity;
    const { originX, originY, resolutionM, width, height } = this.spec;
    const maxX = originX + width * resolutionM;
    const maxY = originY + height * resolutionM;
    for (const angle of angles) {
      const dx = Math.cos(angle);
      const dy = Math.sin(angle);
      const exitX =
        dx > 1e-12 ? (maxX - pose.x) / dx : dx < -1e-12 ? (originX - pose.x) / dx : Infinity;
      const exitY =
        dy > 1e-12 ? (maxY - pose.y) / dy : dy < -1e-12 ? (originY - pose.y) / dy : Infinity;
      const exit = Math.min(exitX, exitY);
      if (exit >= 0 && exit < nearest) nearest = exit;
      const ex = pose.x + limit * Math.cos(angle);
      const ey = pose.y + limit * Math.sin(angle);
      traverseCells(this.spec, pose.x, pose.y, ex, ey, (cx, cy) => {
        if (this.stateOf(cx, cy) !== 'occupied') return true;
        const c = cellCentre(this.spec, cx, cy);
        const d = Math.hypot(c.x - pose.x, c.y - pose.y) - this.spec.resolutionM / 2;
        if (d < nearest) nearest = d;
        return false;
      });
    }
    return nearest;
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
    if (l >= this.model.occupiedAt) return 'occupied';
    if (l <= this.model.freeAt) return 'free';
    return 'unknown';
  }
}
