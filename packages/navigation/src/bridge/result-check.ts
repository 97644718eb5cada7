import type { HALToolResult } from '@hal/types';
import type { ActionReport } from '../decision/provider.js';
import type { Acted, BridgeContext, RunState } from './bridge-context.js';
import { failed, stopRequested } from './navigation-outcome.js';

/** Failed motions in a row that fail the run with HAL_ERROR. */
const MAX_HAL_FAILURES = 3;

/**
 * Turns a motion's HAL result into the bridge's terms: success goes on; COLLISION,
 * EMERGENCY_STOPPED, TIMEOUT, NOT_READY and NOT_CONNECTED end the run at once; INTERRUPTED after
 * `stop()` ends it as stopped; any other failure is reported to the provider, and three in a row
 * fail the run with HAL_ERROR.
 */
export function checkMotionResult(
  ctx: BridgeContext,
  state: RunState,
  action: ActionReport['action'],
  call: string,
  result: HALToolResult,
): Acted {
  const report: ActionReport = { action, success: result.success };
  if (result.error !== undefined) report.error = result.error;
  if (result.code !== undefined) report.code = result.code;
  if (result.success) {
    state.halFailures = 0;
    return { report, moved: true };
  }
  const why = `${call} failed (${result.code ?? 'no code'}): ${result.error ?? 'no message'}`;
  switch (result.code) {
    case 'COLLISION':
      return { report, moved: true, terminal: failed('COLLISION', why) };
    case 'EMERGENCY_STOPPED':
      return { report, moved: false, terminal: failed('EMERGENCY_STOPPED', why) };
    case 'TIMEOUT':
      return { report, moved: true, terminal: failed('TIMEOUT', why) };
    case 'NOT_READY':
    case 'NOT_CONNECTED':
      return { report, moved: false, terminal: failed('HAL_ERROR', why) };
    case 'INTERRUPTED':
      if (ctx.stopRequested) return { report, moved: true, terminal: stopRequested() };
      break;
    default:
      break;
  }
  state.halFailures += 1;
  ctx.logger.warn('navigation: motion failed', { call, code: result.code, error: result.error });
  if (state.halFailures >= MAX_HAL_FAILURES) {
    return {
      report,
      moved: true,
      terminal: failed('HAL_ERROR', `${why} (${MAX_HAL_FAILURES} failures in a row)`),
    };
  }
  // Failed motions count toward halFailures, not toward being stuck.
  return { report, moved: false };
}
