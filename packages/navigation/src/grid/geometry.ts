/**
 * How a rectangular grid of square cells lies in the world (REP-103 plane: x forward, y left,
 * metres). Cell (0, 0) has its lower-left corner at the origin; column index grows with x, row
 * index with y. The flat index of cell (cx, cy) is `cy * width + cx`.
 */
export interface GridSpec {
  /** Cells along x. */
  readonly width: number;
  /** Cells along y. */
  readonly height: number;
  /** Side of one cell, metres. */
  readonly resolutionM: number;
  /** World x of the grid's lower-left corner, metres. */
  readonly originX: number;
  /** World y of the grid's lower-left corner, metres. */
  readonly originY: number;
}

/** A cell's column and row. */
export interface Cell {
  cx: number;
  cy: number;
}

/** A point in the world plane, metres. */
export interface Point {
  x: number;
  y: number;
}

/** A robot pose in the plane: metres, and yaw in radians counter-clockwise from +x (REP-103). */
export interface Pose2D {
  x: number;
  y: number;
  yaw: number;
}

/** The world rectangle a grid covers, metres. */
export interface GridExtent {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/** Straight-line distance between two points, metres. */
export function distance(a: Point, b: Point): number {
  return Math.hypot(a.x - b.x, a.y - b.y);
}

/** The world rectangle the grid covers, from its lower-left corner to its upper-right one. */
export function gridExtent(spec: GridSpec): GridExtent {
  return {
    minX: spec.originX,
    minY: spec.originY,
    maxX: spec.originX + spec.width * spec.resolutionM,
    maxY: spec.originY + spec.height * spec.resolutionM,
  };
}

/** The cell holding world point (x, y), or undefined when it lies outside the grid. */
export function worldToCell(spec: GridSpec, x: number, y: number): Cell | undefined {
  if (!Number.isFinite(x) || !Number.isFinite(y)) return undefined;
  const cx = Math.floor((x - spec.originX) / spec.resolutionM);
  const cy = Math.floor((y - spec.originY) / spec.resolutionM);
  if (cx < 0 || cy < 0 || cx >= spec.width || cy >= spec.height) return undefined;
  return { cx, cy };
}

/** The world point at the centre of cell (cx, cy), metres. */
export function cellCentre(spec: GridSpec, cx: number, cy: number): Point {
  return {
    x: spec.originX + (cx + 0.5) * spec.resolutionM,
    y: spec.originY + (cy + 0.5) * spec.resolutionM,
  };
}

/**
 * Visits the cells whose centres lie within `radiusM` of world point (x, y), around the cell
 * holding it; nothing when the point is off the grid. Cells beyond the grid's edge are visited
 * too (the visitor decides what they mean). The visitor returns false to stop early.
 */
export function forEachCellInDisc(
  spec: GridSpec,
  x: number,
  y: number,
  radiusM: number,
  visit: (cx: number, cy: number) => boolean | void,
): void {
  const centre = worldToCell(spec, x, y);
  if (centre === undefined) return;
  const ring = Math.ceil(radiusM / spec.resolutionM) + 1;
  for (let dy = -ring; dy <= ring; dy += 1) {
    for (let dx = -ring; dx <= ring; dx += 1) {
      const c = cellCentre(spec, centre.cx + dx, centre.cy + dy);
      if (Math.hypot(c.x - x, c.y - y) > radiusM) continue;
      if (visit(centre.cx + dx, centre.cy + dy) === false) return;
    }
  }
}

/** Checks a grid spec, throwing a RangeError that names the bad field. */
export function checkGridSpec(spec: GridSpec): void {
  for (const key of ['width', 'height'] as const) {
    const value = spec[key];
    if (!Number.isInteger(value) || value < 1 || value > 10_000) {
      throw new RangeError(`"${key}" must be an integer from 1 to 10000 cells, got ${value}`);
    }
  }
  if (!Number.isFinite(spec.resolutionM) || spec.resolutionM <= 0) {
    throw new RangeError(`"resolutionM" must be a positive number, got ${spec.resolutionM}`);
  }
  for (const key of ['originX', 'originY'] as const) {
    if (!Number.isFinite(spec[key])) {
      throw new RangeError(`"${key}" must be a finite number, got ${spec[key]}`);
    }
  }
}
