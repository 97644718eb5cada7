// A world on its own, in the task format's `world` ({ map, start, objects }): read from a file and
// made into the simulator's map, so a command can put a robot in the world of a task without a
// task around it (`hal emulate --camera --world FILE`, `hal look --world FILE`).
import { BUILTIN_MAPS, parseMap } from '@hal/simulation';
import type { WorldMap } from '@hal/simulation';
import type { z } from 'zod';
import { parseJsonText, readTextFile, refuse } from './task-file-io.js';
import { COLOURS, WorldSchema } from './task-schema.js';
import type { TaskObject } from './task-schema.js';

/** A task's world: a map (built-in name or written out), the robot's start, named objects. */
export type TaskWorld = z.output<typeof WorldSchema>;
/** A task's world as written in a file (defaults not yet applied). */
export type TaskWorldInput = z.input<typeof WorldSchema>;

/** A world made concrete: the map with the objects in it, and the start in radians. */
export interface RealisedWorld {
  /** The map with the objects added as obstacles (after the map's own); its only start is `start`. */
  map: WorldMap;
  objects: TaskObject[];
  /** The robot's start pose: metres and radians. */
  start: { x: number; y: number; yaw: number };
}

/**
 * `map` (a built-in name or a map) with `objects` added as coloured obstacles and `start` as its
 * only start: the simulator's map of a task's world.
 */
export function mapWithObjects(
  map: TaskWorld['map'],
  objects: readonly TaskObject[],
  start: { x: number; y: number; yaw: number },
): WorldMap {
  const base = typeof map === 'string' ? BUILTIN_MAPS[map] : map;
  return parseMap({
    ...base,
    obstacles: [
      ...base.obstacles,
      ...objects.map((o) =>
        o.kind === 'box'
          ? {
              kind: 'box',
              x: o.x,
              y: o.y,
              width: o.width,
              depth: o.depth,
              height: o.height,
              color: COLOURS[o.colour],
            }
          : {
              kind: 'cylinder',
              x: o.x,
              y: o.y,
              radius: o.radius,
              height: o.height,
              color: COLOURS[o.colour],
            },
      ),
    ],
    starts: [start],
  });
}

/** The simulator's map and the start of a task's world, exactly as written (no seed moves it). */
export function realiseWorld(world: TaskWorld): RealisedWorld {
  const start = { x: world.start.x, y: world.start.y, yaw: (world.start.yawDeg * Math.PI) / 180 };
  const objects = world.objects.map((o) => ({ ...o }));
  return { map: mapWithObjects(world.map, objects, start), objects, start };
}

/** Checks an already parsed world; TASK_INVALID naming `file` and the first bad field. */
export function checkWorld(json: unknown, file: string): TaskWorld {
  const parsed = WorldSchema.safeParse(json);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const field = issue?.path.map(String).join('.') || '(file)';
    refuse(file, field, issue?.message ?? 'is invalid');
  }
  const names = new Set<string>();
  parsed.data.objects.forEach((o, i) => {
    if (names.has(o.name)) refuse(file, `objects.${i}.name`, `repeats "${o.name}"`);
    names.add(o.name);
  });
  return parsed.data;
}

/**
 * Parses the text of a world file (JSON, the `world` of a task: `{ map, start, objects }`) named
 * `file`; throws TASK_INVALID naming the file and the first field that breaks the schema.
 */
export function parseWorldFile(text: string, file: string): TaskWorld {
  const json = parseJsonText(text, file);
  return checkWorld(json, file);
}

/** Reads and checks a world file from disk (Node); see {@link parseWorldFile}. */
export async function loadWorldFile(path: string): Promise<TaskWorld> {
  return parseWorldFile(await readTextFile(path), path);
}
