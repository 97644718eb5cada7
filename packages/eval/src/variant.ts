import { SeededRandom } from '@hal/simulation';
import type { WorldMap } from '@hal/simulation';
import { COLOURS } from './task-schema.js';
import type { ColourName, Task, TaskObject } from './task-schema.js';

const COLOUR_LIST = Object.keys(COLOURS) as ColourName[];
import { mapWithObjects } from './world-file.js';

/** One member of a task's family: the world as a seed placed it. */
export interface TaskVariant {
  task: Task;
  seed: number;
  /** The map with the task's objects added as obstacles (after the map's own). */
  map: WorldMap;
  /** The objects where the seed put them. */
  objects: TaskObject[];
  /** The robot's start pose: metres and radians. */
  start: { x: number; y: number; yaw: number };
}

/** A 32-bit seed for one task and one trial seed (FNV-1a over the id, mixed with the seed). */
export function variantSeed(taskId: string, seed: number): number {
  let h = 0x811c9dc5 ^ (seed >>> 0);
  for (let i = 0; i < taskId.length; i += 1) {
    h ^= taskId.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h >>> 0;
}

/** Rounds to 0.1 mm, so a variant is written down the same everywhere. */
const mm = (v: number) => Math.round(v * 10_000) / 10_000;

/**
 * The member of `task`'s family for a robot, which starts where it stands (its odometry's origin,
 * facing +x): the seed moves only the objects, and draws the seeded faults as ever.
 */
export function realiseAtOrigin(task: Task, seed: number): TaskVariant {
  return realiseTask(
    {
      ...task,
      world: { ...task.world, start: { x: 0, y: 0, yawDeg: 0 } },
      variants: { ...task.variants, startM: 0, yawDeg: 0 },
    },
    seed,
  );
}

/** The member of `task`'s family picked by `seed`. */
export function realiseTask(task: Task, seed: number): TaskVariant {
  const random = new SeededRandom(variantSeed(task.id, seed));
  const jitter = (range: number) => (range === 0 ? 0 : (random.next() * 2 - 1) * range);
  const { startM, yawDeg, objectsM, colours, maybeObjects, mirror } = task.variants;
  let start = {
    x: mm(task.world.start.x + jitter(startM)),
    y: mm(task.world.start.y + jitter(startM)),
    yaw: ((task.world.start.yawDeg + jitter(yawDeg)) * Math.PI) / 180,
  };
  let objects = task.world.objects.map((o) => ({
    ...o,
    x: mm(o.x + jitter(objectsM)),
    y: mm(o.y + jitter(objectsM)),
  }));
  // The draws below come after the jitter, so a task without them is placed as before.
  if (colours)
    objects = objects.map((o) => ({
      ...o,
      colour: COLOUR_LIST[Math.floor(random.next() * COLOUR_LIST.length)] ?? o.colour,
    }));
  if (maybeObjects.length > 0)
    objects = objects.filter((o) => !maybeObjects.includes(o.name) || random.next() < 0.5);
  if (mirror && random.next() < 0.5) {
    start = { x: start.x, y: mm(-start.y), yaw: -start.yaw };
    objects = objects.map((o) => ({ ...o, y: mm(-o.y) }));
  }
  const map = mapWithObjects(task.world.map, objects, start);
  return { task, seed, map, objects, start };
}
