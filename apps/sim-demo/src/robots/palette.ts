/** The most robots the demo puts in its world. */
export const MAX_ROBOTS = 8;

/** Each robot number's colour (1 first): distinct on the light floor and in the plot. */
const COLORS = [
  '#f4b400',
  '#4285f4',
  '#db4437',
  '#0f9d58',
  '#ab47bc',
  '#00acc1',
  '#ff7043',
  '#6d4c41',
] as const;

/** The colour of robot number `n` (1..{@link MAX_ROBOTS}). */
export function robotColor(n: number): string {
  return COLORS[(n - 1) % COLORS.length] ?? COLORS[0];
}

/** The short label of robot number `n`, shown over it and in the panels. */
export function robotLabel(n: number): string {
  return `R${n}`;
}
