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
