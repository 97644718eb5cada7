import { errorMessage, isHalError, withTimeout } from '@hal/types';
import type { Pose2D } from '../grid/geometry.js';
import type { RangeReadings } from '../grid/range-sensor-update.js';
import type { BridgeContext } from './bridge-context.js';
import { failed } from './navigation-outcome.js';
import type { Terminal } from './navigation-outcome.js';
import type { WorldObservation, WorldObserver } from './world-observer.js';

// The bridge's reads of the robot, each bounded by the sensor timeout.

/** The robot's pose, or the terminal of a run that cannot read it. */
export async function readPose(
  ctx: BridgeContext,
): Promise<{ pose: Pose2D } | { terminal: Terminal }> {
  const timeoutMs = ctx.settings.sensorTimeoutMs;
  try {
    const answer = await withTimeout(ctx.hal.locomotion.getPose(), timeoutMs);
    if (answer === undefined) {
      return { terminal: failed('TIMEOUT', `getPose gave no answer within ${timeoutMs} ms`) };
    }
    const { position, rotation } = answer.value;
    const pose = { x: position.x, y: position.y, yaw: rotation.yaw };
    if (![pose.x, pose.y, pose.yaw].every(Number.isFinite)) {
      return { terminal: failed('HAL_ERROR', 'getPose returned a non-finite pose') };
    }
    return { pose };
  } catch (error) {
    return { terminal: failed('HAL_ERROR', `getPose failed: ${errorMessage(error)}`) };
  }
}

/**
 * Reads the range sensors into the world model at `pose`; undefined when range sensors are off,
 * missing (NOT_IMPLEMENTED, or readings marked unavailable: then never asked again), slow or
 * failing.
 */
export async function readRanges(
  ctx: BridgeContext,
  pose: Pose2D,
): Promise<RangeReadings | undefined> {
  const model = ctx.settings.rangeSensors;
  if (model === false || !ctx.sensorsAvailable) return undefined;
  try {
    const answer = await withTimeout(
      ctx.hal.vision.getDistanceSensors(),
      ctx.settings.sensorTimeoutMs,
    );
    if (answer === undefined) {
      ctx.logger.warn('navigation: range sensors gave no answer in time');
      return undefined;
    }
    const readings = answer.value;
    if (readings.source === 'unavailable') {
      ctx.sensorsAvailable = false;
      return undefined;
    }
    ctx.grid.integrateRangeReadings(pose, readings, model);
    return readings;
  } catch (error) {
    if (isHalError(error) && error.code === 'NOT_IMPLEMENTED') {
      ctx.sensorsAvailable = false;
      ctx.logger.info(
        'navigation: the robot has no range sensors; mapping from the known map only',
      );
    } else {
      ctx.logger.warn('navigation: reading the range sensors failed', {
        error: errorMessage(error),
      });
    }
    return undefined;
  }
}

/** A camera frame, or undefined when the camera fails or is slow. */
export async function captureFrame(ctx: BridgeContext): Promise<string | undefined> {
  try {
    const answer = await withTimeout(ctx.hal.vision.captureFrame(), ctx.settings.sensorTimeoutMs);
    return answer?.value;
  } catch (error) {
    ctx.logger.warn('navigation: no camera frame', { error: errorMessage(error) });
    return undefined;
  }
}

/** Stops the wheels, best effort and bounded. */
export async function stopWheels(ctx: BridgeContext): Promise<void> {
  if (!ctx.hal.isReady()) return;
  try {
    await withTimeout(ctx.hal.locomotion.stop(), ctx.settings.sensorTimeoutMs);
  } catch {
    // Best effort: the run is ending anyway.
  }
}

/** Runs the observer for one cycle, bounded by the sensor timeout; never throws. */
export async function observeWorld(
  ctx: BridgeContext,
  observer: WorldObserver,
  observation: WorldObservation,
): Promise<void> {
  const timeoutMs = ctx.settings.sensorTimeoutMs;
  try {
    const done = await withTimeout(
      Promise.resolve().then(() => observer(observation)),
      timeoutMs,
    );
    if (done === undefined) {
      ctx.logger.warn('navigation: the world observer did not finish in time', { timeoutMs });
    }
  } catch (error) {
    ctx.logger.warn('navigation: the world observer failed', { error: errorMessage(error) });
  }
}
