// Runs one `hal drive` action: live pose on stderr while a motion runs, and Ctrl-C during a
// motion stops the robot before the command ends. An open-ended `wheels` drive runs until Ctrl-C.
import { delay, HalError, isHalError, toHalError, withTimeout } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer, Pose } from '@hal/types';
import { CliError } from '../cli-error.js';
import { progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { poseText } from '../pose-text.js';
import { resultError } from '../result-error.js';
import { aborted } from '../wait.js';
import { callFor, isMotion } from './actions.js';
import type { DriveAction } from './actions.js';

export interface DriveOutcome {
  result: HALToolResult;
  /** The pose after the action. */
  pose: Pose;
  /** True when Ctrl-C ended an open-ended drive (the robot was stopped). */
  stoppedByUser: boolean;
}

const LIVE_POSE_MS = 250;
/** How long the stop after Ctrl-C may take before the command gives up waiting. */
const STOP_WAIT_MS = 5000;

/** Prints the pose on stderr every LIVE_POSE_MS until `done` is aborted (people only, not --json). */
async function livePose(
  hal: HardwareAbstractionLayer,
  io: CliIO,
  global: GlobalOptions,
  done: AbortSignal,
): Promise<void> {
  if (global.json) return;
  while (!done.aborted) {
    await delay(LIVE_POSE_MS, done);
    if (done.aborted) return;
    const pose = await hal.locomotion.getPose().catch(() => undefined);
    if (pose !== undefined && !done.aborted) progress(io, global, `  ${poseText(pose, true)}`);
  }
}

/**
 * Stops the robot: undefined once it confirmed the stop, else the error saying why it did not
 * (the HAL's own, or TIMEOUT after STOP_WAIT_MS). A stop is never claimed unconfirmed.
 */
async function stopRobot(hal: HardwareAbstractionLayer): Promise<HalError | undefined> {
  const answer = await withTimeout(
    hal.locomotion.stop().catch((error: unknown) => toHalError(error)),
    STOP_WAIT_MS,
  );
  if (answer === undefined) {
    return new HalError('TIMEOUT', `the robot did not confirm the stop within ${STOP_WAIT_MS} ms`);
  }
  const result = answer.value;
  if (isHalError(result)) return result;
  return result.success ? undefined : resultError(result);
}

export async function runDrive(
  hal: HardwareAbstractionLayer,
  action: DriveAction,
  io: CliIO,
  global: GlobalOptions,
): Promise<DriveOutcome> {
  if (!isMotion(action)) {
    const result = await callFor(hal, action);
    if (!result.success) throw resultError(result);
    return { result, pose: await hal.locomotion.getPose(), stoppedByUser: false };
  }
  const done = new AbortController();
  const live = livePose(hal, io, global, done.signal);
  try {
    const call = callFor(hal, action);
    const interrupted = aborted(io.signal).then(() => 'interrupted' as const);
    const first = await Promise.race([call, interrupted]);
    if (first === 'interrupted') {
      const unstopped = await stopRobot(hal);
      if (unstopped !== undefined) throw unstopped;
      await Promise.race([call.catch(() => undefined), delay(STOP_WAIT_MS, done.signal)]);
      throw new CliError('FAILED', 'interrupted: the robot was stopped', 130);
    }
    if (!first.success) throw resultError(first);
    const openEnded = action.kind === 'wheels' && action.durationMs === undefined;
    if (openEnded) {
      progress(io, global, 'driving; Ctrl-C stops the robot');
      await interrupted;
      const unstopped = await stopRobot(hal);
      if (unstopped !== undefined) throw unstopped;
    }
    return { result: first, pose: await hal.locomotion.getPose(), stoppedByUser: openEnded };
  } finally {
    done.abort();
    await live;
  }
}
