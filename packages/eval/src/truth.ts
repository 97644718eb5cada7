import { castRay, discContact, solidsOf } from '@hal/simulation';
import type { Solid, WorldMap } from '@hal/simulation';
import type { TaskObject } from './task-schema.js';
import type { TaskVariant } from './variant.js';

/*
 * Ground truth: the world as the simulator has it (the map's solids, the objects' true places), for
 * the judge (checks) and the oracle only. An agent under test never reads it: it learns the world
 * through the HAL's calls, which tell only what its sensors could (scan in its odometry's frame, a
 * drifting gyro, a contact without what was touched).
 */

/** The robot's footprint radius in the simulator, metres. */
export const ROBOT_RADIUS_M = 0.07;

/** Distance from a point to an object's surface, metres (0 inside). */
export function distanceToObject(x: number, y: number, o: TaskObject): number {
  if (o.kind === 'cylinder') return Math.max(0, Math.hypot(x - o.x, y - o.y) - o.radius);
  const dx = Math.max(Math.abs(x - o.x) - o.width / 2, 0);
  const dy = Math.max(Math.abs(y - o.y) - o.depth / 2, 0);
  return Math.hypot(dx, dy);
}

/** The solids of the variant's objects (the map's last obstacles), in the objects' order. */
export function objectSolids(variant: TaskVariant): Solid[] {
  const solids = solidsOf(variant.map);
  return solids.slice(solids.length - variant.objects.length);
}

/** The object first hit by a ray from (x, y) along `yaw`, if an object comes before any wall. */
export function objectAhead(
  variant: TaskVariant,
  x: number,
  y: number,
  yaw: number,
): TaskObject | undefined {
  const solids = solidsOf(variant.map);
  const hit = castRay(x, y, yaw, 100, solids);
  if (hit.solid === undefined) return undefined;
  const index = solids.indexOf(hit.solid) - (solids.length - variant.objects.length);
  return index >= 0 ? variant.objects[index] : undefined;
}

/** Free distance along `yaw` from the robot's body to the first solid, metres. */
export function gapAhead(map: WorldMap, x: number, y: number, yaw: number): number {
  return castRay(x, y, yaw, 100, solidsOf(map)).distance - ROBOT_RADIUS_M;
}

/** Which side of the robot has more free space (the open side), from ground truth. */
export function openSide(map: WorldMap, x: number, y: number, yaw: number): 'left' | 'right' {
  const solids = solidsOf(map);
  const left = castRay(x, y, yaw + Math.PI / 2, 100, solids).distance;
  const right = castRay(x, y, yaw - Math.PI / 2, 100, solids).distance;
  return left >= right ? 'left' : 'right';
}

/** Whether a disc of the robot's radius at (x, y) touches any solid of the map. */
export function touchesAnything(map: WorldMap, x: number, y: number): boolean {
  return solidsOf(map).some((s) => discContact(x, y, ROBOT_RADIUS_M, s) !== undefined);
}

/** The start pose's frame: a point `forward` and `left` of the start, in the world. */
export function relativeToStart(
  start: { x: number; y: number; yaw: number },
  forward: number,
  left: number,
): { x: number; y: number } {
  const c = Math.cos(start.yaw);
  const s = Math.sin(start.yaw);
  return { x: start.x + forward * c - left * s, y: start.y + forward * s + left * c };
}

/** An angle wrapped into (-π, π]. */
export function wrapAngle(a: number): number {
  let r = a % (2 * Math.PI);
  if (r > Math.PI) r -= 2 * Math.PI;
  if (r <= -Math.PI) r += 2 * Math.PI;
  return r;
}
