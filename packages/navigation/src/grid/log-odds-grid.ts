import type { GridSpec } from './geometry.js';
import type { CellState, LogOddsModel } from './log-odds.js';

/**
 * What seeding from a map and laying range readings in need of a grid: its cells' states and a
 * way to change their log-odds. `OccupancyGrid` is one; the two updates take this rather
 * than the class, so the class can call them without a circle of imports.
 */
export interface LogOddsGrid {
  readonly spec: GridSpec;
  readonly model: Readonly<LogOddsModel>;
  /** The state of cell (cx, cy); outside the grid: unknown. */
  stateOf(cx: number, cy: number): CellState;
  /** Sets a cell's log-odds (clamped). */
  setLogOdds(cx: number, cy: number, value: number): void;
  /** Adds evidence (a log-odds delta) to a cell. */
  addEvidence(cx: number, cy: number, delta: number): void;
}
