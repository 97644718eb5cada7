import { cellCentre, distance } from '../grid/geometry.js';
import type { Point, Pose2D } from '../grid/geometry.js';
import type { PathPlan } from '../planner/grid-planner.js';
import { sensorsInUse } from './bridge-context.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import { runMotion } from './motion-call.js';
import { recoverFromNoRoute, replanWithoutWeakObstacles } from './recovery.js';
import { rotateArgs, turnDeg } from './turning.js';
import { entersUnknown } from './world-updates.js';

/** How far a start too close to an obstacle may step to a cell the robot may stand on, metres. */
const START_STEP_M = 0.3;

/**
 * MOVE_TO and EXPLORE: plans from the actual pose to `target` and drives the first leg of the
 * route, cut to `maxLegM` (or `unknownLegM` into unknown space, with range sensors), turning to
 * face it first when it lies too far off the heading. A goal too close to an obstacle is replaced
 * by the nearest free cell near it; a start too close to one first steps to the nearest cell the
 * robot may stand on; no route goes to the recovery.
 */
export async function followRoute(
  ctx: BridgeContext,
  state: RunState,
  action: 'MOVE_TO' | 'EXPLORE',
  pose: Pose2D,
  target: Point,
): Promise<Acted> {
  const { grid, settings } = ctx;
  const { goalPoint, plan: first } = planToStandingPoint(ctx, pose, target);
  if (first.status === 'start-blocked' && first.startCell !== undefined) {
    // Too near an obstacle to plan from here: step to the nearest cell the robot may stand on.
    const reach = START_STEP_M / grid.spec.resolutionM;
    const free = grid.obstacles.nearestFree(first.startCell.cx, first.startCell.cy, reach);
    if (free !== undefined) {
      const leg = cellCentre(grid.spec, free.cx, free.cy);
      ctx.events.emit('path', { cycle: state.cycle, target, plan: first, leg });
      return runMotion(ctx, state, action, 'point', { x: leg.x, y: leg.y });
    }
  }
  const plan = replanWithoutWeakObstacles(ctx, first, pose, goalPoint);
  if (plan.status !== 'found') {
    const where = `(${target.x.toFixed(2)}, ${target.y.toFixed(2)})`;
    const message = `no route to ${where}: ${plan.status}`;
    return recoverFromNoRoute(ctx, state, action, pose, plan.status, message);
  }
  state.noPath = 0;
  // The route ends at the goal cell's centre; end it at the target itself when the robot may
  // stand there.
  const waypoints = plan.waypoints.slice();
  if (waypoints.length > 1 && grid.isTraversable(goalPoint.x, goalPoint.y)) {
    waypoints[waypoints.length - 1] = goalPoint;
  }
  const next = waypoints.find((p, k) => k > 0 && distance(pose, p) > 0.01) ?? waypoints.at(-1);
  if (next === undefined || distance(pose, next) <= 0.01) {
    return { report: { action, success: true }, moved: false };
  }
  const leg = cutLeg(ctx, pose, next);
  ctx.events.emit('path', { cycle: state.cycle, target, plan: { ...plan, waypoints }, leg });
  // Look before driving: with range sensors or a world observer (a camera), first turn to face
  // the leg, so the front sensor or the camera has seen it before the wheels go (the next cycle
  // re-plans with what it saw).
  const turn = turnDeg(pose.yaw, Math.atan2(leg.y - pose.y, leg.x - pose.x));
  const looking = sensorsInUse(ctx) || settings.observe !== undefined;
  if (settings.faceFirst && looking && Math.abs(turn) > settings.faceFirstDeg) {
    return runMotion(ctx, state, action, 'turn', rotateArgs(turn));
  }
  return runMotion(ctx, state, action, 'point', { x: leg.x, y: leg.y });
}

/**
 * Plans to `target`, or, when the robot may not stand there, to the nearest free cell within the
 * goal tolerance plus the robot's footprint.
 */
function planToStandingPoint(
  ctx: BridgeContext,
  pose: Pose2D,
  target: Point,
): { goalPoint: Point; plan: PathPlan } {
  const { grid } = ctx;
  const plan = grid.plan(pose, target);
  if (plan.status !== 'goal-blocked' || plan.goalCell === undefined)
    return { goalPoint: target, plan };
  const reach =
    (ctx.settings.goalToleranceM + grid.robotRadiusM + grid.clearanceM) / grid.spec.resolutionM;
  const free = grid.obstacles.nearestFree(plan.goalCell.cx, plan.goalCell.cy, reach);
  if (free === undefined) return { goalPoint: target, plan };
  const goalPoint = cellCentre(grid.spec, free.cx, free.cy);
  return { goalPoint, plan: grid.plan(pose, goalPoint) };
}

/**
 * The point the robot drives to this cycle: `next`, or the point `maxLegM` toward it (into unknown
 * space, with range sensors, `unknownLegM`: each cycle's readings then map what the robot passes,
 * and a thin wall seen side-on from far apart poses does not come out as dashes).
 */
function cutLeg(ctx: BridgeContext, pose: Pose2D, next: Point): Point {
  const { maxLegM, unknownLegM } = ctx.settings;
  const span = distance(pose, next);
  const limit =
    sensorsInUse(ctx) && entersUnknown(ctx.grid, pose, next)
      ? Math.min(maxLegM, unknownLegM)
      : maxLegM;
  if (span <= limit) return next;
  return {
    x: pose.x + ((next.x - pose.x) * limit) / span,
    y: pose.y + ((next.y - pose.y) * limit) / span,
  };
}
