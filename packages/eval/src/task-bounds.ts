// Where a task puts things: the robot's start and the objects must lie inside the arena's walls
// (with their seeded jitter), and the robot must not start inside an object, a wall or an
// obstacle of the map. A task that breaks this would load and then fail for no fault of the
// agent's (an oracle "failing" 100 m away from a box the simulator never placed).
import { BUILTIN_MAPS, discContact, solidsOf } from '@hal/simulation';
import type { WorldMap } from '@hal/simulation';
import type { Task, TaskObject } from './task-schema.js';
import { ROBOT_RADIUS_M } from './truth.js';

/** A place a task puts something where it cannot be: the field and why. */
export interface PlacementProblem {
  /** The field under the task, e.g. `world.objects.2.x`. */
  field: string;
  why: string;
}

const m = (v: number) => `${Math.round(v * 1000) / 1000} m`;

/** The task's map with its defaults filled in. */
function mapOf(task: Task): WorldMap {
  return typeof task.world.map === 'string' ? BUILTIN_MAPS[task.world.map] : task.world.map;
}

/** Half the object's size along x and along y, metres. */
function halfSize(o: TaskObject): { x: number; y: number } {
  return o.kind === 'box' ? { x: o.width / 2, y: o.depth / 2 } : { x: o.radius, y: o.radius };
}

/**
 * Checks that `reach` (a half-size, metres) around (x, y), moved by up to `jitter` either way,
 * stays inside the arena; answers why not, or undefined.
 */
function outside(
  map: WorldMap,
  x: number,
  y: number,
  reach: { x: number; y: number },
  jitter: number,
): { axis: 'x' | 'y'; limit: number } | undefined {
  const limitX = map.arena.width / 2 - reach.x - jitter;
  const limitY = map.arena.height / 2 - reach.y - jitter;
  if (Math.abs(x) > limitX) return { axis: 'x', limit: limitX };
  if (Math.abs(y) > limitY) return { axis: 'y', limit: limitY };
  return undefined;
}

/** Whether a disc of the robot's radius at (x, y) overlaps the object. */
function overlaps(o: TaskObject, x: number, y: number): boolean {
  if (o.kind === 'cylinder') return Math.hypot(x - o.x, y - o.y) < o.radius + ROBOT_RADIUS_M;
  const cx = Math.min(Math.max(x, o.x - o.width / 2), o.x + o.width / 2);
  const cy = Math.min(Math.max(y, o.y - o.depth / 2), o.y + o.depth / 2);
  return Math.hypot(x - cx, y - cy) < ROBOT_RADIUS_M;
}

/**
 * The first thing of `task` placed where it cannot be: the start or an object outside the
 * arena (jitter included), a point to reach outside it, or a start that overlaps an object, a
 * wall or an obstacle.
 */
export function placementProblem(task: Task): PlacementProblem | undefined {
  const map = mapOf(task);
  const arena = `the ${map.arena.width} x ${map.arena.height} m arena`;
  const { start } = task.world;
  const { startM, objectsM } = task.variants;
  const robot = { x: ROBOT_RADIUS_M, y: ROBOT_RADIUS_M };
  const startOut = outside(map, start.x, start.y, robot, startM);
  if (startOut !== undefined) {
    return {
      field: `world.start.${startOut.axis}`,
      why:
        `puts the robot outside ${arena}: its centre must be within ±${m(startOut.limit)} ` +
        `(the arena is centred on the origin; its radius ${m(ROBOT_RADIUS_M)} and the start jitter ${m(startM)} included), got ${m(start[startOut.axis])}`,
    };
  }
  for (const [i, o] of task.world.objects.entries()) {
    const out = outside(map, o.x, o.y, halfSize(o), objectsM);
    if (out !== undefined) {
      return {
        field: `world.objects.${i}.${out.axis}`,
        why:
          `puts "${o.name}" outside ${arena}: its centre must be within ±${m(out.limit)} ` +
          `(the arena is centred on the origin; its size and the object jitter ${m(objectsM)} included), got ${m(o[out.axis])}`,
      };
    }
  }
  for (const [i, check] of task.checks.entries()) {
    if (check.kind !== 'reach-point') continue;
    const out = outside(map, check.x, check.y, robot, 0);
    if (out !== undefined) {
      return {
        field: `checks.${i}.${out.axis}`,
        why:
          `is a point the robot cannot reach inside ${arena}: its centre stays within ±${m(out.limit)} ` +
          `(its radius ${m(ROBOT_RADIUS_M)} included), got ${m(check[out.axis])}`,
      };
    }
  }
  const hit = task.world.objects.find((o) => overlaps(o, start.x, start.y));
  if (hit !== undefined)
    return {
      field: 'world.start',
      why: `puts the robot inside "${hit.name}" at (${m(start.x)}, ${m(start.y)})`,
    };
  const solid = solidsOf(map).find(
    (s) => discContact(start.x, start.y, ROBOT_RADIUS_M, s) !== undefined,
  );
  if (solid !== undefined)
    return {
      field: 'world.start',
      why: `puts the robot inside ${solid.role === 'arena' ? "the arena's wall" : `the map's ${solid.role} ${solid.index}`} at (${m(start.x)}, ${m(start.y)})`,
    };
  return undefined;
}
