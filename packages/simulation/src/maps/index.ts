import { parseMap } from '../map.js';
import type { WorldMap } from '../map.js';
import empty from './empty.json' with { type: 'json' };
import maze from './maze.json' with { type: 'json' };
import obstacles from './obstacles.json' with { type: 'json' };
import room from './room.json' with { type: 'json' };

/** The maps that ship with the package, checked against the map schema. */
export const BUILTIN_MAPS: Readonly<Record<'empty' | 'obstacles' | 'maze' | 'room', WorldMap>> =
  Object.freeze({
    empty: parseMap(empty),
    obstacles: parseMap(obstacles),
    maze: parseMap(maze),
    room: parseMap(room),
  });

/** The name of a built-in map. */
export type BuiltinMapName = keyof typeof BUILTIN_MAPS;
