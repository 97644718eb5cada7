import { floorPointOfPixel, horizonRow } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import type { FloorModel } from './floor-model.js';
import type { RgbaImage } from './image.js';

/** What the camera sees along one image column: how far the floor is free. */
export interface FreeSpaceColumn {
  /** The image column. */
  column: number;
  /** Bearing of the boundary point from the robot's heading, radians (left positive). */
  bearingRad: number;
  /**
   * Distance from the robot's centre to the first thing that is not floor, metres; when `hit`
   * is false, the floor is free at least this far (the range limit).
   */
  distanceM: number;
  /** Whether something that is not floor was seen (false: free up to the range limit). */
  hit: boolean;
  /**
   * Whether the thing seen reaches below the image's bottom edge: it is at `distanceM` or
   * nearer (the camera cannot see the floor nearer than that).
   */
  atEdge: boolean;
  /** Where the column's nearest visible floor is, robot frame, metres (the start of its view). */
  from: { x: number; y: number };
  /** The boundary (or range-limit) point, robot frame, metres. */
  to: { x: number; y: number };
}

/** Options of {@link scanFreeSpace}. */
export interface FreeSpaceOptions {
  /** Farthest distance the floor is judged at, metres from the robot's centre. Default 2.5. */
  maxRangeM: number;
  /** Columns between two scanned ones (1 = every column). Default 2. */
  columnStep: number;
  /** Rows of non-floor in a row that make an obstacle (one is noise). Default 2. */
  minRun: number;
}

export const DEFAULT_FREE_SPACE: Readonly<FreeSpaceOptions> = Object.freeze({
  maxRangeM: 2.5,
  columnStep: 2,
  minRun: 2,
});

interface ColumnGeometry {
  /** Per row, the floor point of its lower edge (robot frame), or undefined above the horizon. */
  rowPoints: Array<{ x: number; y: number } | undefined>;
  /** The highest row scanned: beyond it the floor is past the range limit. */
  topRow: number;
}

const geometryCache = new WeakMap<CameraProjection, Map<string, ColumnGeometry[]>>();

function geometry(p: CameraProjection, options: FreeSpaceOptions): ColumnGeometry[] {
  const key = `${options.maxRangeM}`;
  let byKey = geometryCache.get(p);
  if (byKey === undefined) {
    byKey = new Map();
    geometryCache.set(p, byKey);
  }
  const cached = byKey.get(key);
  if (cached !== undefined) return cached;
  const { width, height } = p.camera;
  const horizon = Math.max(0, Math.ceil(horizonRow(p)));
  const columns: ColumnGeometry[] = [];
  for (let col = 0; col < width; col += 1) {
    const rowPoints: Array<{ x: number; y: number } | undefined> = new Array(height);
    let topRow = height;
    for (let row = height - 1; row >= horizon; row -= 1) {
      const point = floorPointOfPixel(p, col + 0.5, row + 1);
      rowPoints[row] = point;
      if (point === undefined || Math.hypot(point.x, point.y) > options.maxRangeM) break;
      topRow = row;
    }
    columns.push({ rowPoints, topRow });
  }
  byKey.set(key, columns);
  return columns;
}

/**
 * Per image column (every `columnStep`th), the distance to the first pixel from the bottom that
 * is not floor, through the camera model: the nearest obstacle at that bearing.
 */
export function scanFreeSpace(
  image: RgbaImage,
  floor: FloorModel,
  projection: CameraProjection,
  options: FreeSpaceOptions = DEFAULT_FREE_SPACE,
): FreeSpaceColumn[] {
  const { width, height, data } = image;
  const columns = geometry(projection, options);
  const out: FreeSpaceColumn[] = [];
  const half = Math.floor(options.columnStep / 2);
  for (let col = Math.min(half, width - 1); col < width; col += options.columnStep) {
    const g = columns[col];
    if (g === undefined) continue;
    const from = g.rowPoints[height - 1] ?? { x: 0, y: 0 };
    let run = 0;
    let boundary = -1;
    for (let row = height - 1; row >= g.topRow; row -= 1) {
      if (floor.isFloorAt(data, (row * width + col) * 4)) {
        run = 0;
        continue;
      }
      run += 1;
      if (run >= options.minRun) {
        boundary = row + run - 1;
        break;
      }
    }
    // A run cut short at the top of the scanned rows still counts.
    if (boundary < 0 && run > 0 && run >= Math.min(options.minRun, height - g.topRow)) {
      boundary = g.topRow + run - 1;
    }
    if (boundary >= 0) {
      const to = g.rowPoints[boundary] ?? from;
      out.push({
        column: col,
        bearingRad: Math.atan2(to.y, to.x),
        distanceM: Math.hypot(to.x, to.y),
        hit: true,
        atEdge: boundary === height - 1,
        from,
        to,
      });
    } else {
      const last = g.rowPoints[g.topRow] ?? from;
      const scale = options.maxRangeM / Math.max(1e-9, Math.hypot(last.x, last.y));
      const to = { x: last.x * Math.min(1, scale), y: last.y * Math.min(1, scale) };
      out.push({
        column: col,
        bearingRad: Math.atan2(to.y, to.x),
        distanceM: Math.min(options.maxRangeM, Math.hypot(last.x, last.y)),
        hit: false,
        atEdge: false,
        from,
        to,
      });
    }
  }
  return out;
}
