import { cellCentre, gridExtent, worldToCell } from './geometry.js';
import type { Pose2D } from './geometry.js';
import type { LogOddsGrid } from './log-odds-grid.js';
import { traverseCells } from './raycast.js';

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

/**
 * Lays one range reading into the grid: a ray from (x, y) at `angle` (radians, world frame)
 * that saw an obstacle `rangeM` away (free evidence up to it, occupied evidence in the cell it
 * ends in) or, when `hit` is false, nothing within `rangeM` (free evidence only).
 */
export function integrateRayIntoGrid(
  grid: LogOddsGrid,
  x: number,
  y: number,
  angle: number,
  rangeM: number,
  hit: boolean,
): void {
  if (![x, y, angle, rangeM].every(Number.isFinite) || rangeM < 0) return;
  const { spec, model } = grid;
  const ex = x + rangeM * Math.cos(angle);
  const ey = y + rangeM * Math.sin(angle);
  const end = worldToCell(spec, ex, ey);
  const endIndex = end === undefined ? -1 : end.cy * spec.width + end.cx;
  traverseCells(spec, x, y, ex, ey, (cx, cy) => {
    if (cy * spec.width + cx === endIndex) return false;
    grid.addEvidence(cx, cy, model.miss);
    return true;
  });
  if (hit && end !== undefined) grid.addEvidence(end.cx, end.cy, model.hit);
}

/**
 * Lays the front, left and right (and, when present, front-left and front-right) readings
 * taken at `pose` into the grid. Each sensor adds free evidence across its field of view up to
 * its reading. A reading short of the maximum range adds occupied evidence on the arc of the
 * field of view at that distance: on the whole arc when the grid does not already explain the
 * reading (no occupied cell in the cone at about that distance), else on the arc's unknown
 * cells only. Non-finite readings are ignored.
 */
export function integrateReadingsIntoGrid(
  grid: LogOddsGrid,
  pose: Pose2D,
  readings: RangeReadings,
  sensors: Partial<RangeSensorModel> = {},
): void {
  const { spec } = grid;
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
    // The direction at fraction t (0..1) across the cone; a one-ray sensor looks straight.
    const across = (t: number) => pose.yaw + offset + (rays === 1 ? 0 : (t - 0.5) * fov);
    const angles: number[] = [];
    for (let i = 0; i < rays; i += 1) angles.push(across(rays === 1 ? 0 : i / (rays - 1)));
    // What the map already explains: the nearest occupied cell across the cone. A reading
    // that far (or farther) adds no new obstacle; a shorter one means something unexpected.
    const expected = hit
      ? nearestOccupied(grid, pose, angles, range + 4 * spec.resolutionM)
      : Infinity;
    const unexpected = hit && range < expected - 2 * spec.resolutionM;
    // Free evidence across the cone: nothing in it is nearer than the reading.
    for (const angle of angles) integrateRayIntoGrid(grid, pose.x, pose.y, angle, range, false);
    if (!hit) continue;
    // Occupied evidence on the arc at the reading's distance: a cone's reading does not say
    // where across the cone the obstacle is, so the whole arc is suspect (free evidence from
    // other views clears the parts that are not). When the grid already explains the reading,
    // only the arc's unknown cells are marked: they may hide more of the same obstacle (the
    // rest of a wall seen in dashes), while cells known free stay free.
    const arc = new Set<number>();
    const steps = Math.max(1, Math.ceil((range * fov) / (spec.resolutionM / 2)));
    for (let k = 0; k <= steps; k += 1) {
      const angle = across(k / steps);
      const end = worldToCell(
        spec,
        pose.x + range * Math.cos(angle),
        pose.y + range * Math.sin(angle),
      );
      if (end === undefined) continue;
      if (!unexpected && grid.stateOf(end.cx, end.cy) !== 'unknown') continue;
      arc.add(end.cy * spec.width + end.cx);
    }
    for (const index of arc) {
      grid.addEvidence(index % spec.width, Math.floor(index / spec.width), grid.model.hit);
    }
  }
}

/**
 * Distance to the nearest occupied cell along any of the rays, up to `limit` metres. The edge
 * of the grid counts as a wall (as it does for planning): the arena's walls usually lie there.
 */
function nearestOccupied(
  grid: LogOddsGrid,
  pose: Pose2D,
  angles: readonly number[],
  limit: number,
): number {
  const { spec } = grid;
  const { minX, minY, maxX, maxY } = gridExtent(spec);
  let nearest = Infinity;
  for (const angle of angles) {
    const dx = Math.cos(angle);
    const dy = Math.sin(angle);
    const exitX = dx > 1e-12 ? (maxX - pose.x) / dx : dx < -1e-12 ? (minX - pose.x) / dx : Infinity;
    const exitY = dy > 1e-12 ? (maxY - pose.y) / dy : dy < -1e-12 ? (minY - pose.y) / dy : Infinity;
    const exit = Math.min(exitX, exitY);
    if (exit >= 0 && exit < nearest) nearest = exit;
    const ex = pose.x + limit * Math.cos(angle);
    const ey = pose.y + limit * Math.sin(angle);
    traverseCells(spec, pose.x, pose.y, ex, ey, (cx, cy) => {
      if (grid.stateOf(cx, cy) !== 'occupied') return true;
      const c = cellCentre(spec, cx, cy);
      const d = Math.hypot(c.x - pose.x, c.y - pose.y) - spec.resolutionM / 2;
      if (d < nearest) nearest = d;
      return false;
    });
  }
  return nearest;
}
