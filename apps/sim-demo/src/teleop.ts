/** Wheel powers (-255..255) for a set of held keys: arrows or WASD; none held: undefined. */
export function powersFor(keys: ReadonlySet<string>): { left: number; right: number } | undefined {
  const up = keys.has('ArrowUp') || keys.has('w');
  const down = keys.has('ArrowDown') || keys.has('s');
  const left = keys.has('ArrowLeft') || keys.has('a');
  const right = keys.has('ArrowRight') || keys.has('d');
  const forward = (up ? 1 : 0) - (down ? 1 : 0);
  const turn = (left ? 1 : 0) - (right ? 1 : 0);
  if (forward === 0 && turn === 0) return undefined;
  if (forward === 0) return { left: -200 * turn, right: 200 * turn };
  // Driving with a turn key held: an arc, the inner wheel at 40 %.
  const inner = turn === 0 ? 1 : 0.4;
  const l = turn > 0 ? inner : 1;
  const r = turn < 0 ? inner : 1;
  return { left: Math.round(255 * forward * l), right: Math.round(255 * forward * r) };
}

/** The keys teleop listens to (lower-cased letters). */
export const TELEOP_KEYS = new Set([
  'ArrowUp',
  'ArrowDown',
  'ArrowLeft',
  'ArrowRight',
  'w',
  'a',
  's',
  'd',
]);
