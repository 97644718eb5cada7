import type { Point, Pose2D } from '../grid/geometry.js';
import type { PathPlan } from '../planner/grid-planner.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import { runMotion } from './motion-call.js';
import { failed } from './navigation-outcome.js';
import type { Terminal } from './navigation-outcome.js';
import { markObstacleAhead, pointAlong } from './world-updates.js';

/** How far a nudge or a back-off drives, cm. */
const NUDGE_CM = 10;

/**
 * Plans again after forgetting the obstacles only one or two readings saw, when there is no route
 * and there are such obstacles: stray readings may have closed the way (the sensors will put back
 * whatever is really there). Otherwise answers `plan` as it is.
 */
export function replanWithoutWeakObstacles(
  ctx: BridgeContext,
  plan: PathPlan,
  pose: Pose2D,
  goal: Point,
): PathPlan {
  if (plan.status !== 'unreachable' || ctx.grid.forgetWeakObstacles() === 0) return plan;
  ctx.logger.info('navigation: no route; forgot weak obstacles and planned again');
  return ctx.grid.plan(pose, goal);
}

/**
 * No route this cycle: the seed's recovery (nudge forward 10 cm) when the cells ahead are free,
 * else a quarter turn to look elsewhere; too many cycles in a row without a route fail the run.
 */
export async function recoverFromNoRoute(
  ctx: BridgeContext,
  state: RunState,
  action: 'MOVE_TO' | 'EXPLORE',
  pose: Pose2D,
  code: string,
  message: string,
): Promise<Acted> {
  const report = { action, success: false, code, error: message };
  state.noPath += 1;
  if (state.noPath >= ctx.settings.maxNoPathCycles) {
    return {
      report,
      moved: false,
      terminal: failed('UNREACHABLE', `${message}, for ${state.noPath} cycles in a row`),
    };
  }
  const ahead = pointAlong(pose, NUDGE_CM / 100 + ctx.grid.spec.resolutionM);
  const acted = ctx.grid.isTraversable(ahead.x, ahead.y)
    ? await runMotion(ctx, state, action, 'forward', { distanceCm: NUDGE_CM })
    : await runMotion(ctx, state, action, 'turn', { direction: 'left', degrees: 90 });
  if (acted.terminal !== undefined) return acted;
  return { ...acted, report };
}

/**
 * Motions that left the robot where it was: whatever is ahead is marked in the world model (so
 * the planner routes round it), the robot backs off when the cells behind are free, and turns a
 * quarter turn, alternating sides.
 */
export async function recoverFromStuck(
  ctx: BridgeContext,
  state: RunState,
  pose: Pose2D,
): Promise<Terminal | undefined> {
  const { grid } = ctx;
  ctx.logger.warn('navigation: the robot is stuck; recovering', { recovery: state.recoveries });
  markObstacleAhead(grid, pose, grid.robotRadiusM + grid.spec.resolutionM);
  const back = pointAlong(pose, -(NUDGE_CM / 100 + grid.spec.resolutionM));
  if (grid.isTraversable(back.x, back.y)) {
    const backed = await runMotion(ctx, state, 'MOVE_TO', 'backward', { distanceCm: NUDGE_CM });
    if (backed.terminal !== undefined) return backed.terminal;
  }
  const turned = await runMotion(ctx, state, 'MOVE_TO', 'turn', {
    direction: state.recoveries % 2 === 1 ? 'left' : 'right',
    degrees: 90,
  });
  return turned.terminal;
}
