import type { World } from '@hal/simulation';

/** Room kept between a new robot and anything else, metres. */
const CLEARANCE_M = 0.06;
/** Spacing of the grid of places tried around the map's first start, metres. */
const SPACING_M = 0.4;

/**
 * Where a new robot of radius `radius` can start in `world`: the map's start poses in order,
 * then places on a grid spreading out from the first start, the first one that keeps
 * {@link CLEARANCE_M} from every solid and robot and lies inside the arena. Undefined when none
 * does (a crowded small map).
 */
export function freeStart(
  world: World,
  radius: number,
): { x: number; y: number; yaw: number } | undefined {
  const starts = world.map.starts;
  const first = starts[0] ?? { x: 0, y: 0, yaw: 0 };
  const grid: Array<{ x: number; y: number; yaw: number }> = [];
  for (let i = -6; i <= 6; i += 1) {
    for (let j = -6; j <= 6; j += 1) {
      grid.push({ x: first.x + i * SPACING_M, y: first.y + j * SPACING_M, yaw: first.yaw });
    }
  }
  // Nearest to the first start first (a stable sort keeps the order of equal distances).
  grid.sort(
    (p, q) => Math.hypot(p.x - first.x, p.y - first.y) - Math.hypot(q.x - first.x, q.y - first.y),
  );
  const candidates = [...starts, ...grid];
  const { width, height } = world.map.arena;
  const reach = radius + CLEARANCE_M;
  return candidates.find(
    (p) =>
      Math.abs(p.x) + reach <= width / 2 &&
      Math.abs(p.y) + reach <= height / 2 &&
      world.contactAt(p.x, p.y, reach) === undefined,
  );
}
