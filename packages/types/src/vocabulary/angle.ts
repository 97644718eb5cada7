/**
 * Wraps an angle, radians, to (-pi, pi]: -pi itself becomes pi, so one heading has one value.
 * Any finite angle works (a large one keeps the precision `Math.sin`/`Math.cos` give it); NaN and
 * +-Infinity give NaN, which a caller's validation should have refused before.
 */
export function normalizeAngle(angle: number): number {
  const wrapped = Math.atan2(Math.sin(angle), Math.cos(angle));
  return wrapped <= -Math.PI ? Math.PI : wrapped;
}

/** The signed difference `a - b`, radians, wrapped to (-pi, pi]: how far `b` must turn to face `a`. */
export function angleDifference(a: number, b: number): number {
  return normalizeAngle(a - b);
}
