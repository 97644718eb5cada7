import { normalizeAngle } from '@hal/types';
import { distance, worldToCell } from '../grid/geometry.js';
import type { Pose2D } from '../grid/geometry.js';
import type { ActionReport, DecisionContext } from '../decision/provider.js';
import { askProvider } from './ask-provider.js';
import type { BridgeContext, RunState } from './bridge-context.js';
import { executeAction } from './execute-action.js';
import type { NavigationEvents } from './navigation-events.js';
import { failed, stopRequested } from './navigation-outcome.js';
import type { Terminal } from './navigation-outcome.js';
import { recoverFromStuck } from './recovery.js';
import { poseFromResult } from './result-pose.js';
import { captureFrame, observeWorld, readPose, readRanges } from './sensing.js';
import { DEG } from './turning.js';
import { refreshPose } from './world-updates.js';

/** Closer than this, metres, and the robot has not moved. */
const STILL_M = 0.01;

/**
 * The run's cycles, until one ends it: each cycle checks the stop request, the emergency stop,
 * the goal and the caps, then senses (pose, range sensors, frame, the world observer), decides
 * and acts, and reads the pose again. Motions that leave the robot where it was trigger the stuck recovery.
 */
export async function runCycles(
  ctx: BridgeContext,
  state: RunState,
  signal: AbortSignal,
  started: number,
): Promise<Terminal> {
  const { hal, grid, settings } = ctx;
  if (!hal.isReady()) return failed('HAL_ERROR', 'the HAL is not ready (call initialize())');
  if (state.goal !== null && worldToCell(grid.spec, state.goal.x, state.goal.y) === undefined) {
    const { x, y } = state.goal;
    return failed('UNREACHABLE', `the goal (${x}, ${y}) lies outside the world model`);
  }
  const first = await readPose(ctx);
  if ('terminal' in first) return first.terminal;
  let pose = first.pose;
  state.trajectory.push(pose);
  let lastResult: ActionReport | undefined;

  for (;;) {
    const checked = checkBeforeCycle(ctx, state, pose, started);
    if ('terminal' in checked) return checked.terminal;
    const elapsed = checked.elapsedMs;
    state.cycle += 1;

    // Sense: the world model follows the actual pose.
    grid.markFree(pose.x, pose.y, grid.robotRadiusM);
    const readings = await readRanges(ctx, pose);
    const wantsFrame = ctx.provider.wantsFrame === true;
    const observer = settings.observe;
    const frame = wantsFrame || observer !== undefined ? await captureFrame(ctx) : undefined;
    if (observer !== undefined) {
      await observeWorld(ctx, observer, { cycle: state.cycle, frame, pose, grid });
    }
    const cycleEvent: NavigationEvents['cycle'] = { cycle: state.cycle, pose, elapsedMs: elapsed };
    if (readings !== undefined) cycleEvent.readings = readings;
    ctx.events.emit('cycle', cycleEvent);

    // Decide.
    const context: DecisionContext = {
      cycle: state.cycle,
      goal: state.goal,
      goalToleranceM: settings.goalToleranceM,
      pose,
      grid,
    };
    if (readings !== undefined) context.readings = readings;
    if (wantsFrame && frame !== undefined) context.frame = frame;
    if (lastResult !== undefined) context.lastResult = lastResult;
    const decided = await askProvider(ctx, context, signal);
    if ('terminal' in decided) return decided.terminal;
    const decision = decided.decision;
    ctx.events.emit('decision', { cycle: state.cycle, provider: ctx.provider.name, decision });

    // Act.
    const resultBefore = state.lastHalResult;
    const acted = await executeAction(ctx, state, decision, pose);
    if (acted.terminal !== undefined) {
      if (acted.moved) await refreshPose(ctx, state);
      return acted.terminal;
    }
    lastResult = acted.report;
    // the motion's result, when this action called one
    const called = state.lastHalResult === resultBefore ? undefined : state.lastHalResult;
    const reported = settings.poseFromResults ? poseFromResult(called, pose) : undefined;
    const after = reported === undefined ? await readPose(ctx) : { pose: reported };
    if ('terminal' in after) return after.terminal;
    const still = isStill(pose, after.pose);
    pose = after.pose;
    state.trajectory.push(pose);

    // Stuck: motion commands that leave the robot where it was.
    if (acted.moved && still) state.stuck += 1;
    else if (!still) state.stuck = 0;
    if (state.stuck >= 2) {
      state.stuck = 0;
      state.recoveries += 1;
      if (state.recoveries > settings.maxStuckRecoveries) {
        const recoveries = settings.maxStuckRecoveries;
        return failed('STUCK', `the robot did not move despite ${recoveries} recoveries`);
      }
      const recovered = await recoverFromStuck(ctx, state, pose);
      if (recovered !== undefined) return recovered;
      const again = await readPose(ctx);
      if ('terminal' in again) return again.terminal;
      pose = again.pose;
      state.trajectory.push(pose);
    }
  }
}

/**
 * What ends the run before a cycle starts (a stop, the emergency stop, the goal, or a cap), else
 * the run's elapsed time.
 */
function checkBeforeCycle(
  ctx: BridgeContext,
  state: RunState,
  pose: Pose2D,
  started: number,
): { terminal: Terminal } | { elapsedMs: number } {
  const { settings } = ctx;
  if (ctx.stopRequested) return { terminal: stopRequested() };
  if (ctx.hal.safety.isEmergencyStopped()) {
    return { terminal: failed('EMERGENCY_STOPPED', 'the emergency stop is latched') };
  }
  if (state.goal !== null && distance(pose, state.goal) <= settings.goalToleranceM) {
    const away = distance(pose, state.goal).toFixed(3);
    const message = `reached the goal (within ${away} m)`;
    return { terminal: { status: 'reached', reason: 'GOAL_REACHED', message } };
  }
  const elapsedMs = settings.now() - started;
  if (elapsedMs > settings.maxDurationMs) {
    return { terminal: failed('TIME_LIMIT', `no result within ${settings.maxDurationMs} ms`) };
  }
  if (state.cycle >= settings.maxCycles) {
    return { terminal: failed('MAX_CYCLES', `no result within ${settings.maxCycles} cycles`) };
  }
  return { elapsedMs };
}

/** Whether the robot stayed where it was: moved less than 1 cm and turned less than 1 degree. */
function isStill(before: Pose2D, after: Pose2D): boolean {
  const moved = distance(after, before);
  const turned = Math.abs(normalizeAngle(after.yaw - before.yaw));
  return moved < STILL_M && turned < DEG;
}
