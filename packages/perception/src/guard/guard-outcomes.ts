// The failures the guard answers a motion with, each recorded and logged with the same words:
// an obstacle, a blind guard, a refused reverse, a motion cancelled before it started.
import { failureResult, HalError, isHalError, errorMessage } from '@hal/types';
import type { HALToolResult } from '@hal/types';
import type { GuardContext } from './guard-context.js';
import type { GuardStop } from './guard-status.js';
import type { Sighting } from './sighting.js';

const round = (v: number, places = 3) => Math.round(v * 10 ** places) / 10 ** places;

/**
 * OBSTACLE_AHEAD: `motion` refused (`before`) or stopped after `travelledM` (`during`) by what
 * `seen` shows within the stand-off; recorded as a guard stop.
 */
export function obstacleResult(
  ctx: GuardContext,
  motion: string,
  seen: Sighting,
  when: 'before' | 'during',
  travelledM: number,
): HALToolResult {
  const { standoffM } = ctx.settings;
  const stop: GuardStop = {
    motion,
    distanceM: round(seen.aheadM),
    source: seen.source,
    atEdge: seen.atEdge,
    when,
    travelledM: round(travelledM),
    at: Date.now(),
  };
  ctx.record.obstacle(stop);
  const ahead = `${seen.atEdge ? 'at most ' : ''}${stop.distanceM} m ahead (${seen.source})`;
  const done = when === 'before' ? 'refused, nothing moved' : `stopped after ${stop.travelledM} m`;
  const message = `${motion}: ${done}: an obstacle ${ahead}; the guard stops ${standoffM} m short of what it sees`;
  ctx.log.info(message, { ...stop });
  return failureResult(
    ctx.hal.mode,
    Date.now(),
    new HalError('OBSTACLE_AHEAD', message, {
      details: {
        distanceM: stop.distanceM,
        source: stop.source,
        atEdge: stop.atEdge,
        standoffM,
        when,
        travelledM: stop.travelledM,
      },
    }),
  );
}

/** The guard could not look ahead (`error`): `motion` refused, or stopped if a leg had run. */
export function blindResult(
  ctx: GuardContext,
  motion: string,
  moved: boolean,
  error: unknown,
): HALToolResult {
  const why = errorMessage(error);
  const message = `${motion}: ${moved ? 'stopped' : 'refused'} rather than drive blind: the guard cannot see ahead (${why})`;
  ctx.record.blind(motion, message);
  ctx.log.warn(message);
  const code = isHalError(error) ? error.code : 'HARDWARE_ERROR';
  return failureResult(
    ctx.hal.mode,
    Date.now(),
    new HalError(code, message, { details: { guard: 'blind' }, cause: error }),
  );
}

/** TIMEOUT: the watcher saw nothing for `sinceMs` while `motion` ran, and stopped it. */
export function blindTripResult(ctx: GuardContext, motion: string, sinceMs: number): HALToolResult {
  const message = `${motion}: stopped rather than drive blind: the guard saw nothing for ${sinceMs} ms`;
  ctx.record.blind(motion, message);
  ctx.log.warn(message);
  return failureResult(
    ctx.hal.mode,
    Date.now(),
    new HalError('TIMEOUT', message, { details: { guard: 'blind', sinceMs } }),
  );
}

/** NOT_IMPLEMENTED: a reverse refused (the guard cannot see behind the robot). */
export function reverseRefusal(ctx: GuardContext, motion: string): HALToolResult {
  return failureResult(
    ctx.hal.mode,
    Date.now(),
    new HalError(
      'NOT_IMPLEMENTED',
      `${motion}: the guard cannot see behind the robot and refuses a reverse: turn and drive forward`,
      { details: { guard: 'reverse' } },
    ),
  );
}

/** INTERRUPTED: a newer call (a stop, an e-stop, another motion) came before `motion` started. */
export function cancelledResult(ctx: GuardContext, motion: string): HALToolResult {
  return failureResult(
    ctx.hal.mode,
    Date.now(),
    new HalError('INTERRUPTED', `${motion}: stopped before it started`),
  );
}
