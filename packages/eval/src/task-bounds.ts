// Where a task puts things: the robot's start and the objects must lie inside the arena's walls
// (with their seeded jitter), and the robot must not start inside an object, a wall or an
// obstacle of the map. A task that breaks this would load and then fail for no fault of the
// agent's (an oracle "failing" 100 m away from a box the simulator never placed).
import { BUILTIN_MAPS, solidsOf } from '@hal/simulation';
import type { Solid, WorldMap } from '@hal/simulation';
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

/**
 * A plan-view footprint as a rectangle rounded by `r`: every point within `r` of the rectangle
 * [x0, x1] x [y0, y1]. A box is a rectangle with r = 0, a disc a point rectangle with its radius;
 * jitter of ± j either way grows the rectangle by j, so one footprint covers every seed's place.
 */
interface Footprint {
  x0: number;
  x1: number;
  y0: number;
  y1: number;
  r: number;
}

function disc(x: number, y: number, r: number, jitter: number): Footprint {
  return { x0: x - jitter, x1: x + jitter, y0: y - jitter, y1: y + jitter, r };
}

function ofObject(o: TaskObject, jitter: number): Footprint {
  if (o.kind === 'cylinder') return disc(o.x, o.y, o.radius, jitter);
  const { x, y } = halfSize(o);
  return {
    x0: o.x - x - jitter,
    x1: o.x + x + jitter,
    y0: o.y - y - jitter,
    y1: o.y + y + jitter,
    r: 0,
  };
}

function ofSolid(s: Solid): Footprint {
  return s.kind === 'box'
    ? { x0: s.minX, x1: s.maxX, y0: s.minY, y1: s.maxY, r: 0 }
    : disc(s.x, s.y, s.radius, 0);
}

/** Whether two footprints overlap (touching at one point is no overlap). */
function overlap(a: Footprint, b: Footprint): boolean {
  const dx = Math.max(0, a.x0 - b.x1, b.x0 - a.x1);
  const dy = Math.max(0, a.y0 - b.y1, b.y0 - a.y1);
  const reach = a.r + b.r;
  return reach === 0 ? boxesCross(a, b) : Math.hypot(dx, dy) < reach;
}

/** Two rectangles share more than an edge. */
function boxesCross(a: Footprint, b: Footprint): boolean {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/** A solid of the map in words, e.g. "the map's obstacle 2". */
function solidName(s: Solid): string {
  return s.role === 'arena' ? "the arena's wall" : `the map's ${s.role} ${s.index}`;
}

/**
 * The first thing of `task` placed where it cannot be: the start or an object outside the
 * arena (jitter included), a point to reach outside it, a start that some seed puts on an object,
 * a wall or an obstacle, or an object that some seed puts on a wall or an obstacle of the map
 * (the start ± its jitter, each object ± its jitter, the robot's radius and the objects' sizes
 * included: the check is exact for the boxes and discs of plan view, not sampled); with
 * `variants.mirror`, of the world mirrored across y = 0 as well.
 */
export function placementProblem(task: Task): PlacementProblem | undefined {
  const problem = placementOf(task);
  if (problem !== undefined || !task.variants.mirror) return problem;
  // a seed may mirror the start and the objects across y = 0: that world must fit the map too
  const { world } = task;
  const mirrored: Task = {
    ...task,
    world: {
      ...world,
      start: { ...world.start, y: -world.start.y, yawDeg: -world.start.yawDeg },
      objects: world.objects.map((o) => ({ ...o, y: -o.y })),
    },
  };
  const flipped = placementOf(mirrored);
  return flipped === undefined
    ? undefined
    : {
        ...flipped,
        why: `${flipped.why} (in the world mirrored across y = 0, which "variants.mirror" draws)`,
      };
}

function placementOf(task: Task): PlacementProblem | undefined {
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
  const stops = stopProblem(task, map, arena);
  if (stops !== undefined) return stops;
  const at = `(${m(start.x)}, ${m(start.y)})${startM > 0 ? ` ± ${m(startM)}` : ''}`;
  const robotAt = disc(start.x, start.y, ROBOT_RADIUS_M, startM);
  const solids = solidsOf(map).filter((s) => s.role !== 'arena');
  const solid = solids.find((s) => overlap(robotAt, ofSolid(s)));
  if (solid !== undefined)
    return {
      field: 'world.start',
      why: `puts the robot (radius ${m(ROBOT_RADIUS_M)}) at ${at}, where it can lie inside ${solidName(solid)}`,
    };
  for (const [i, o] of task.world.objects.entries()) {
    const placed = ofObject(o, objectsM);
    if (overlap(robotAt, placed))
      return {
        field: 'world.start',
        why:
          `puts the robot (radius ${m(ROBOT_RADIUS_M)}) at ${at}, where it can lie inside "${o.name}"` +
          (objectsM > 0 ? ` (placed ± ${m(objectsM)})` : ''),
      };
    const under = solids.find((s) => overlap(placed, ofSolid(s)));
    if (under !== undefined)
      return {
        field: `world.objects.${i}`,
        why: `puts "${o.name}" at (${m(o.x)}, ${m(o.y)})${objectsM > 0 ? ` ± ${m(objectsM)}` : ''}, where it can lie inside ${solidName(under)}`,
      };
  }
  return undefined;
}

/**
 * The first stop of a `visit-in-order` check that cannot be a stop: an object the world lacks, a
 * point outside the arena, or a place the robot already stands at when it starts (some seed's
 * start within its reach: visited without a move).
 */
function stopProblem(task: Task, map: WorldMap, arena: string): PlacementProblem | undefined {
  const { start } = task.world;
  const { startM, objectsM } = task.variants;
  for (const [i, check] of task.checks.entries()) {
    if (check.kind !== 'visit-in-order') continue;
    for (const [j, stop] of check.stops.entries()) {
      const field = `checks.${i}.stops.${j}`;
      let nearest: number;
      if ('object' in stop) {
        const o = task.world.objects.find((w) => w.name === stop.object);
        if (o === undefined) {
          const known = task.world.objects.map((w) => w.name).join(', ') || 'none';
          return {
            field: `${field}.object`,
            why: `names "${stop.object}", which the world lacks (objects: ${known})`,
          };
        }
        if (task.variants.maybeObjects.includes(o.name))
          return {
            field: `${field}.object`,
            why: `names "${o.name}", which "variants.maybeObjects" lets a seed leave out`,
          };
        const size = halfSize(o);
        const dx = Math.max(0, Math.abs(start.x - o.x) - size.x);
        const dy = Math.max(0, Math.abs(start.y - o.y) - size.y);
        nearest = Math.hypot(dx, dy) - Math.SQRT2 * (startM + objectsM);
      } else {
        const out = outside(map, stop.x, stop.y, { x: ROBOT_RADIUS_M, y: ROBOT_RADIUS_M }, 0);
        if (out !== undefined)
          return {
            field: `${field}.${out.axis}`,
            why:
              `is a point the robot cannot reach inside ${arena}: its centre stays within ±${m(out.limit)} ` +
              `(its radius ${m(ROBOT_RADIUS_M)} included), got ${m(stop[out.axis])}`,
          };
        nearest = Math.hypot(start.x - stop.x, start.y - stop.y) - Math.SQRT2 * startM;
      }
      if (nearest <= stop.withinM)
        return {
          field,
          why: `is within ${m(stop.withinM)} of the start for some seed: the robot would visit it without moving`,
        };
    }
  }
  return undefined;
}
