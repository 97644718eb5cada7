import {
  argsFromObject,
  invokeSpec,
  isHalError,
  maxLinearSpeedMPerS,
  errorMessage,
  motionCall,
  withTimeout,
} from '@hal/types';
import type { CallMotion, HALToolResult } from '@hal/types';
import type { ActionReport } from '../decision/provider.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import type { BridgeSettings } from './bridge-options.js';
import { checkMotionResult } from './result-check.js';
import { stopWheels } from './sensing.js';
import { markGuardedObstacle } from './world-updates.js';

const DEG = Math.PI / 180;

/** A motion call's arguments, by name (they go into the `result` event as they are). */
export type MotionArgs = Record<string, number | string>;

/**
 * Runs the HAL's call for `motion` (`point`: to `x`, `y`; `turn`; `forward`, `backward`; see
 * CallMotion) with a timeout (after which the wheels are stopped), emits `result`, and turns its
 * result into the bridge's terms (see {@link checkMotionResult}).
 */
export async function runMotion(
  ctx: BridgeContext,
  state: RunState,
  action: ActionReport['action'],
  motion: CallMotion,
  args: MotionArgs,
): Promise<Acted> {
  const spec = motionCall(motion);
  const call = spec.name;
  const timeoutMs = motionTimeoutMs(ctx.settings, motion, args);
  let result: HALToolResult;
  try {
    // a drive to a point goes at the bridge's speed, on the floor (z 0)
    const named = motion === 'point' ? { ...args, z: 0, speed: ctx.settings.speed } : args;
    const invoked = invokeSpec(ctx.hal, spec, argsFromObject(spec, named));
    const answer = await withTimeout(invoked as Promise<HALToolResult>, timeoutMs);
    if (answer === undefined) {
      await stopWheels(ctx);
      result = {
        success: false,
        code: 'TIMEOUT',
        error: `${call} did not finish within ${Math.round(timeoutMs)} ms (the bridge's limit)`,
        timestamp: ctx.settings.now(),
        mode: ctx.hal.mode,
      };
    } else {
      result = answer.value;
    }
  } catch (error) {
    // A HAL must not throw from a motion call; treat it as a hardware error if one does.
    result = {
      success: false,
      code: isHalError(error) ? error.code : 'HARDWARE_ERROR',
      error: errorMessage(error),
      timestamp: ctx.settings.now(),
      mode: ctx.hal.mode,
    };
  }
  ctx.events.emit('result', { cycle: state.cycle, call, args, result });
  state.lastHalResult = result;
  if (result.code === 'OBSTACLE_AHEAD') markGuardedObstacle(ctx, state, motion, args, result);
  return checkMotionResult(ctx, state, action, call, result);
}

/** A motion's timeout: its expected duration at the robot's speed, doubled, plus a margin. */
export function motionTimeoutMs(
  settings: BridgeSettings,
  motion: CallMotion,
  args: MotionArgs,
): number {
  const speed = Math.min(settings.speed ?? Infinity, maxLinearSpeedMPerS(settings.robot));
  const halfBaseM = settings.robot.wheelBaseCm / 200;
  let metres = 0;
  if (motion === 'point') {
    // A turn of up to half a revolution, then the straight leg.
    metres = Math.PI * halfBaseM + settings.maxLegM * 1.5;
  } else if (motion === 'turn') {
    metres = Number(args['degrees']) * DEG * halfBaseM;
  } else {
    metres = Number(args['distanceCm']) / 100;
  }
  return settings.motionTimeoutMarginMs + (2 * metres * 1000) / speed;
}
