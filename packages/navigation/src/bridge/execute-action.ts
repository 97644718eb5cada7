import { findFrontier } from '../grid/frontier.js';
import { distance } from '../grid/geometry.js';
import type { Pose2D } from '../grid/geometry.js';
import type { ActionReport } from '../decision/provider.js';
import type { NavigationDecision } from '../decision/schema.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import { followRoute } from './follow-route.js';
import { runMotion } from './motion-call.js';
import { recoverFromNoRoute } from './recovery.js';
import { DEG, rotateArgs, turnDeg } from './turning.js';

/** Turns smaller than this, degrees, are not made. */
const MIN_TURN_DEG = 0.5;

/**
 * Carries out a checked decision: MOVE_TO and EXPLORE follow the A* route one leg per cycle,
 * ROTATE_TO turns the shorter way to an absolute heading, STOP ends the run.
 */
export async function executeAction(
  ctx: BridgeContext,
  state: RunState,
  decision: NavigationDecision,
  pose: Pose2D,
): Promise<Acted> {
  const action = decision.action;
  switch (action.type) {
    case 'STOP':
      return stop(ctx, state, decision, pose);
    case 'ROTATE_TO': {
      // Absolute heading, degrees, counter-clockwise from +x (see the decision schema).
      const delta = turnDeg(pose.yaw, action.yaw_deg * DEG);
      if (Math.abs(delta) < MIN_TURN_DEG) {
        return { report: { action: 'ROTATE_TO', success: true }, moved: false };
      }
      return runMotion(ctx, state, 'ROTATE_TO', 'turn', rotateArgs(delta));
    }
    case 'EXPLORE': {
      const frontier = findFrontier(ctx.grid, pose);
      if (frontier === undefined) {
        const message = 'no reachable unexplored area is left';
        return recoverFromNoRoute(ctx, state, 'EXPLORE', pose, 'no-frontier', message);
      }
      return followRoute(ctx, state, 'EXPLORE', pose, frontier.target);
    }
    case 'MOVE_TO':
      return followRoute(ctx, state, 'MOVE_TO', pose, { x: action.x, y: action.y });
  }
}

/**
 * STOP ends the run. With a goal, "reached" is judged from the actual pose, not from the
 * provider's `goal_reached` claim; with none (exploration), `goal_reached` says it is complete.
 */
function stop(
  ctx: BridgeContext,
  state: RunState,
  decision: NavigationDecision,
  pose: Pose2D,
): Acted {
  const report: ActionReport = { action: 'STOP', success: true };
  if (state.goal === null) {
    const terminal = decision.goal_reached
      ? {
          status: 'reached' as const,
          reason: 'EXPLORATION_COMPLETE' as const,
          message: `exploration complete: ${decision.reasoning}`,
        }
      : {
          status: 'stopped' as const,
          reason: 'PROVIDER_STOPPED' as const,
          message: `the provider stopped: ${decision.reasoning}`,
        };
    return { report, moved: false, terminal };
  }
  const away = distance(pose, state.goal);
  if (away <= ctx.settings.goalToleranceM) {
    return {
      report,
      moved: false,
      terminal: { status: 'reached', reason: 'GOAL_REACHED', message: 'reached the goal' },
    };
  }
  const claim = decision.goal_reached ? ' (it claimed the goal was reached)' : '';
  return {
    report,
    moved: false,
    terminal: {
      status: 'stopped',
      reason: 'PROVIDER_STOPPED',
      message: `the provider stopped ${away.toFixed(2)} m from the goal${claim}: ${decision.reasoning}`,
    },
  };
}
