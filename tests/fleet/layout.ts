// Where the fleet tests put their robots: robot 0 leads at the origin, the others stand on a grid
// behind it, COLUMNS abreast, SPACING_M apart; each follower's formation offset is where it
// starts relative to the leader, so the formation keeps the grid's shape.

export const COLUMNS = 7;
export const SPACING_M = 0.25;

/** Start pose of robot `index` (0: the leader). */
export function gridStart(index: number): { x: number; y: number; yaw: number } {
  if (index === 0) return { x: 0, y: 0, yaw: 0 };
  const row = Math.floor((index - 1) / COLUMNS) + 1;
  const column = ((index - 1) % COLUMNS) - Math.floor(COLUMNS / 2);
  return { x: -row * SPACING_M, y: column * SPACING_M, yaw: 0 };
}

/** Device id of robot `index` in a fleet named `prefix`. */
export function deviceId(prefix: string, index: number): string {
  return `${prefix}${String(index).padStart(2, '0')}`;
}

/** Start pose of robot `index` in single file: each SPACING_M behind the one before. */
export function columnStart(index: number): { x: number; y: number; yaw: number } {
  return { x: -index * SPACING_M, y: 0, yaw: 0 };
}
