import { HalError, isHalError } from '@hal/types';
import type { HalContext } from './context.js';

/**
 * What the firmware does when the host goes quiet, for error messages: the one stop that needs
 * no link, and the robot's own figure for when it happens.
 */
function hostTimeoutText(ctx: HalContext): string {
  return (
    'its firmware stops the motors by itself once it has heard nothing from this host for ' +
    `its host timeout (${ctx.robot().hostTimeoutMs} ms)`
  );
}

/** The error of a `stop()` the robot never acknowledged: no stop is claimed. */
export function unacknowledgedStop(ctx: HalContext, cause: HalError): HalError {
  return new HalError(
    'NOT_CONNECTED',
    `the robot could not be told to stop (it did not acknowledge "stop"); ${hostTimeoutText(ctx)}`,
    {
      cause,
      details: {
        ...cause.details,
        stopConfirmed: false,
        hostTimeoutMs: ctx.robot().hostTimeoutMs,
      },
    },
  );
}

/**
 * Runs a motion call; if it loses the link (NOT_CONNECTED), sends one stop on the safety lane
 * (short once the link is known dead) and fails with an error that says whether the robot
 * acknowledged it, and, when it did not, what stops the robot instead.
 */
export async function unlessLinkLost<T>(ctx: HalContext, work: () => Promise<T>): Promise<T> {
  try {
    return await work();
  } catch (error) {
    if (!isHalError(error) || error.code !== 'NOT_CONNECTED') throw error;
    const stopped = await ctx.safetyCommand('stop', {}).catch(() => undefined);
    const lost = `the link to the robot failed during the motion (${error.message})`;
    if (stopped !== undefined) {
      throw new HalError('NOT_CONNECTED', `${lost}; the robot acknowledged a stop after it`, {
        cause: error,
        details: { ...error.details, stopConfirmed: true },
      });
    }
    throw new HalError(
      'NOT_CONNECTED',
      `${lost}; the robot could not be told to stop: ${hostTimeoutText(ctx)}`,
      {
        cause: error,
        details: {
          ...error.details,
          stopConfirmed: false,
          hostTimeoutMs: ctx.robot().hostTimeoutMs,
        },
      },
    );
  }
}
