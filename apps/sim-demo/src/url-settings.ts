import { BUILTIN_MAPS } from '@hal/simulation';
import type { BuiltinMapName } from '@hal/simulation';
import { RENDER_SETTINGS } from './render-profile.js';
import type { RenderSetting } from './render-profile.js';
import { MAX_ROBOTS } from './robots/palette.js';

/** The built-in maps, in the order the map menu lists them. */
export const MAP_NAMES = Object.keys(BUILTIN_MAPS) as BuiltinMapName[];

/** The simulation speeds the speed menu offers. */
const SPEEDS = [1, 2, 5, 10, 20];

/**
 * What the page's URL asks for (`?map=maze&speed=10&robots=3&render=light`), with defaults for
 * anything else.
 */
export function readUrlSettings(search: string): {
  mapName: BuiltinMapName;
  speed: number;
  robots: number;
  render: RenderSetting;
} {
  const params = new URLSearchParams(search);
  const requestedMap = params.get('map');
  const mapName: BuiltinMapName = MAP_NAMES.includes(requestedMap as BuiltinMapName)
    ? (requestedMap as BuiltinMapName)
    : 'obstacles';
  const requestedSpeed = Number(params.get('speed') ?? '5');
  const speed = SPEEDS.includes(requestedSpeed) ? requestedSpeed : 5;
  const requestedRobots = Number(params.get('robots') ?? '1');
  const robots =
    Number.isInteger(requestedRobots) && requestedRobots >= 1 && requestedRobots <= MAX_ROBOTS
      ? requestedRobots
      : 1;
  const requestedRender = params.get('render');
  const render = RENDER_SETTINGS.find((setting) => setting === requestedRender) ?? 'auto';
  return { mapName, speed, robots, render };
}
