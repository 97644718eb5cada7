import { OccupancyGrid } from '@hal/navigation';
import type { PathPlan, Point } from '@hal/navigation';
import type { WorldMap } from '@hal/simulation';
import type { Task, TaskObject } from './task-schema.js';
import { distanceToObject, ROBOT_RADIUS_M } from './truth.js';
import type { TaskVariant } from './variant.js';

/** Clearance the planner keeps beyond the robot's radius, metres. */
const CLEARANCE_M = 0.03;

/** The planner's route on the known map (obstacles inflated by the robot's radius). */
export function planRoute(map: WorldMap, from: Point, to: Point): PathPlan {
  const grid = OccupancyGrid.fromMap(map, {
    robotRadiusM: ROBOT_RADIUS_M,
    clearanceM: CLEARANCE_M,
  });
  return grid.plan(from, to);
}

/**
 * Where to stand to reach an object: points around it `withinM` / 2 beyond the planner's
 * clearance, the one with the shortest route first. Undefined when none can be reached.
 */
export function approachObject(
  map: WorldMap,
  from: Point,
  object: TaskObject,
  withinM: number,
): { point: Point; plan: PathPlan } | undefined {
  const reach =
    ROBOT_RADIUS_M + CLEARANCE_M + Math.max(0.02, (withinM - ROBOT_RADIUS_M - CLEARANCE_M) / 2);
  let best: { point: Point; plan: PathPlan } | undefined;
  for (let k = 0; k < 16; k += 1) {
    const a = (k * Math.PI) / 8;
    // walk out from the centre along the ray until the surface is `reach` away
    let point: Point = { x: object.x, y: object.y };
    for (let r = 0; r < 3; r += 0.01) {
      point = { x: object.x + r * Math.cos(a), y: object.y + r * Math.sin(a) };
      if (distanceToObject(point.x, point.y, object) >= reach) break;
    }
    if (distanceToObject(point.x, point.y, object) > withinM) continue;
    const plan = planRoute(map, from, point);
    if (plan.status !== 'found') continue;
    if (best === undefined || plan.lengthM < best.plan.lengthM) best = { point, plan };
  }
  return best;
}

/** The planner's shortest route for a task, metres, where the task has a place to reach. */
export function optimalPathM(task: Task, variant: TaskVariant): number | null {
  const check = task.checks[0];
  if (check === undefined) return null;
  const { start } = variant;
  switch (check.kind) {
    case 'displacement':
      return Math.hypot(check.forwardM, check.leftM);
    case 'return':
      return 2 * check.minExcursionM;
    case 'reach-point': {
      const plan = planRoute(variant.map, start, { x: check.x, y: check.y });
      return plan.status === 'found' ? plan.lengthM : null;
    }
    case 'reach-object': {
      const object = variant.objects.find((o) => o.name === check.object);
      if (object === undefined) return null;
      return approachObject(variant.map, start, object, check.withinM)?.plan.lengthM ?? null;
    }
    default:
      return null;
  }
}
