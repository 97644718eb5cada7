import { isHalError, maxLinearSpeedMPerS } from '@hal/types';
import type { HALToolResult } from '@hal/types';
import type { ActionReport } from '../decision/provider.js';
import { errorMessage } from '../errors.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import type { BridgeSettings } from './bridge-options.js';
import type { MotionCall } from './navigation-events.js';
import { checkMotionResult } from './result-check.js';
import { stopWheels } from './sensing.js';
import { TIMED_OUT, withTimeout } from './timeouts.js';

const DEG = Math.PI / 180;

/** A motion call's arguments, by name (they go into the `result` event as they are). */
export type MotionArgs = Record<string, number | string>;

/**
 * Runs one motion call with a timeout (after which the wheels are stopped), emits `result`, and
 * turns its result into the bridge's terms (see {@link checkMotionResult}).
 */
export async function runMotion(
  ctx: BridgeContext,
  state: RunState,
  action: ActionReport['action'],
  call: MotionCall,
  args: MotionArgs,
): Promise<Acted> {
  const timeoutMs = motionTimeoutMs(ctx.settings, call, args);
  let result: HALToolResult;
  try {
    const answer = await withTimeout(invoke(ctx, call, args), timeoutMs);
    if (answer === TIMED_OUT) {
      await stopWheels(ctx);
      result = {
        success: false,
        code: 'TIMEOUT',
        error: `${call} did not finish within ${Math.round(timeoutMs)} ms (the bridge's limit)`,
        timestamp: ctx.settings.now(),
        mode: ctx.hal.mode,
      };
    } else {
      result = answer;
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
  return checkMotionResult(ctx, state, action, call, result);
}

function invoke(ctx: BridgeContext, call: MotionCall, args: MotionArgs): Promise<HALToolResult> {
  const loco = ctx.hal.locomotion;
  switch (call) {
    case 'moveTo':
      return loco.moveTo(args['x'] as number, args['y'] as number, 0, ctx.settings.speed);
    case 'rotate':
      return loco.rotate(args['direction'] as 'left' | 'right', args['degrees'] as number);
    case 'moveForward':
      return loco.moveForward(args['distanceCm'] as number);
    case 'moveBackward':
      return loco.moveBackward(args['distanceCm'] as number);
  }
}

/** A motion's timeout: its expected duration at the robot's speed, doubled, plus a margin. */
export function motionTimeoutMs(
  settings: BridgeSettings,
  call: MotionCall,
  args: MotionArgs,
): number {
  const speed = Math.min(settings.speed ?? Infinity, maxLinearSpeedMPerS(settings.robot));
  const halfBaseM = settings.robot.wheelBaseCm / 200;
  let metres = 0;
  if (call === 'moveTo') {
    // A turn of up to half a revolution, then the straight leg.
    metres = Math.PI * halfBaseM + settings.maxLegM * 1.5;
  } else if (call === 'rotate') {
    metres = Number(args['degrees']) * DEG * halfBaseM;
  } else {
    metres = Number(args['distanceCm']) / 100;
  }
  return settings.motionTimeoutMarginMs + (2 * metres * 1000) / speed;
}
