// Seeded navigation scenarios on the simulation's built-in maps: a start pose and a goal, both
// where the robot fits with room to spare, joined by a route. Shared by the end-to-end tests.
import { OccupancyGrid } from '@hal/navigation';
import type { Point } from '@hal/navigation';
import { BUILTIN_MAPS, SeededRandom } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';

export interface Scenario {
  map: BuiltinMapName;
  seed: number;
  start: { x: number; y: number; yaw: number };
  goal: Point;
}

/** A point at least `margin` metres (beyond the planner's inflation) from every obstacle. */
function roomy(grid: OccupancyGrid, p: Point, margin: number): boolean {
  for (let a = 0; a < 8; a += 1) {
    const q = {
      x: p.x + margin * Math.cos((a * Math.PI) / 4),
      y: p.y + margin * Math.sin((a * Math.PI) / 4),
    };
    if (!grid.isTraversable(q.x, q.y)) return false;
  }
  return grid.isTraversable(p.x, p.y);
}

/** `count` scenarios per map, from seeds 1..count, each at least `minDistanceM` apart. */
export function scenarios(count: number, minDistanceM = 1.5): Scenario[] {
  const out: Scenario[] = [];
  for (const name of Object.keys(BUILTIN_MAPS) as BuiltinMapName[]) {
    const map = BUILTIN_MAPS[name];
    const grid = new OccupancyGrid();
    grid.seedFromMap(map);
    for (let seed = 1; seed <= count; seed += 1) {
      const random = new SeededRandom(seed * 7919 + name.length);
      const pick = (): Point => {
        for (;;) {
          const p = { x: (random.next() - 0.5) * 4.6, y: (random.next() - 0.5) * 4.6 };
          if (roomy(grid, p, 0.08)) return p;
        }
      };
      for (;;) {
        const start = pick();
        const goal = pick();
        if (Math.hypot(goal.x - start.x, goal.y - start.y) < minDistanceM) continue;
        if (grid.plan(start, goal).status !== 'found') continue;
        out.push({
          map: name,
          seed,
          start: { ...start, yaw: (random.next() - 0.5) * 2 * Math.PI },
          goal,
        });
        break;
      }
    }
  }
  return out;
}
