/** What the world model believes about one cell. */
export type CellState = 'unknown' | 'free' | 'occupied';

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

/** The state a log-odds value stands for under `model`. */
export function classifyLogOdds(model: Readonly<LogOddsModel>, l: number): CellState {
  if (l >= model.occupiedAt) return 'occupied';
  if (l <= model.freeAt) return 'free';
  return 'unknown';
}

/** `value` clamped to the model's [min, max]. */
export function clampLogOdds(model: Readonly<LogOddsModel>, value: number): number {
  return Math.min(model.max, Math.max(model.min, value));
}
