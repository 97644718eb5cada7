// Keyboard driving: each key becomes one HAL call, made in order; a live pose line on stderr.
// A drive key sets an open-ended drive that runs until the next key (space stops it).
import { delay } from '@hal/types';
import type { HalErrorCode, HALToolResult, HardwareAbstractionLayer, Pose } from '@hal/types';
import { emit, progress } from '../io.js';
import type { GlobalOptions } from '../io.js';
import { poseText } from '../pose-text.js';
import { aborted } from '../wait.js';
import { parseKeys } from './keys.js';
import type { TeleopKey } from './keys.js';
import type { StatusLineIO } from './status-line.js';
import type { TerminalInput } from './terminal.js';

export interface TeleopOptions {
  /** Wheel power for driving straight, 1..255. */
  power: number;
  /** Wheel power for turning in place, 1..255. */
  turnPower: number;
}

export interface TeleopSummary {
  /** The keys acted on, in order. */
  keys: TeleopKey[];
  /** The pose at the end (`confirmed: false` when the robot could not confirm it). */
  pose: Pose;
  emergencyStopped: boolean;
  /** The final stop: acknowledged by the robot, or the HAL's failed result saying why not. */
  stop: { stopped: true } | { stopped: false; code: HalErrorCode; error: string };
}

const POSE_LINE_MS = 200;

function callFor(
  hal: HardwareAbstractionLayer,
  key: Exclude<TeleopKey, 'quit'>,
  o: TeleopOptions,
): Promise<HALToolResult> {
  const loco = hal.locomotion;
  switch (key) {
    case 'forward':
      return loco.drive(o.power, o.power);
    case 'back':
      return loco.drive(-o.power, -o.power);
    case 'left':
      return loco.drive(-o.turnPower, o.turnPower);
    case 'right':
      return loco.drive(o.turnPower, -o.turnPower);
    case 'stop':
      return loco.stop();
    case 'estop':
      return hal.safety.emergencyStop('teleop: e pressed');
    case 'reset':
      return hal.safety.resetEmergencyStop();
  }
}

/**
 * Reads keys from `stdin` (already in raw mode) and drives `hal` until q, Ctrl-C, the end of
 * input or an abort of `io.signal`; then stops the robot, and reports whether it confirmed the
 * stop (it is never said to be stopped when it did not).
 */
export async function runTeleop(
  hal: HardwareAbstractionLayer,
  stdin: TerminalInput,
  io: StatusLineIO,
  global: GlobalOptions,
  options: TeleopOptions,
): Promise<TeleopSummary> {
  const pending: TeleopKey[] = [];
  const acted: TeleopKey[] = [];
  let wake: (() => void) | undefined;
  // q, Ctrl-C, the end of input or the command's abort: ends the session even mid-call
  const stopping = new AbortController();
  const end = (): void => {
    stopping.abort();
    wake?.();
  };
  let status = 'ready';
  const report = (key: TeleopKey, result: HALToolResult): void => {
    status = result.success ? key : `${key} refused: ${result.code ?? 'FAILED'}`;
    if (global.json) emit(io, global, { key, result }, () => '');
  };
  const urgent: Promise<unknown>[] = [];
  let stopped: HALToolResult;
  const onData = (chunk: Buffer | string): void => {
    for (const key of parseKeys(typeof chunk === 'string' ? chunk : chunk.toString('latin1'))) {
      if (key === 'quit') {
        end();
        return;
      }
      if (key === 'stop' || key === 'estop') {
        // never queued behind a slow call: sent at once, and the drive keys before it dropped
        pending.length = 0;
        acted.push(key);
        urgent.push(callFor(hal, key, options).then((result) => report(key, result)));
      } else {
        pending.push(key);
      }
    }
    wake?.();
  };
  stdin.on('data', onData);
  stdin.once('end', end);
  io.signal.addEventListener('abort', end, { once: true });

  const lineDone = new AbortController();
  const poseLine = (async () => {
    while (!lineDone.signal.aborted && !global.json) {
      const pose = await hal.locomotion.getPose().catch(() => undefined);
      const estop = hal.safety.isEmergencyStopped() ? '  E-STOP' : '';
      const link = hal.isReady() ? '' : '  LINK LOST';
      if (pose !== undefined && !lineDone.signal.aborted) {
        io.showLine(`${poseText(pose)}  ${status}${estop}${link}`);
      }
      await delay(POSE_LINE_MS, lineDone.signal);
    }
  })();

  try {
    const ending = aborted(stopping.signal).then(() => undefined);
    while (!stopping.signal.aborted) {
      const key = pending.shift();
      if (key === undefined) {
        await new Promise<void>((resolve) => (wake = resolve));
        wake = undefined;
        continue;
      }
      if (key === 'quit') break;
      acted.push(key);
      // a call that hangs (a lost link) must not keep the user from quitting
      const result = await Promise.race([callFor(hal, key, options), ending]);
      if (result === undefined) break;
      report(key, result);
    }
  } finally {
    stdin.off('data', onData);
    stdin.off('end', end);
    io.signal.removeEventListener('abort', end);
    await Promise.allSettled(urgent);
    lineDone.abort();
    await poseLine;
    io.endLine();
    stopped = await hal.locomotion.stop().catch((error: unknown): HALToolResult => ({
      success: false,
      code: 'HARDWARE_ERROR',
      error: `the stop failed: ${String(error)}`,
      timestamp: Date.now(),
      mode: hal.mode,
    }));
  }
  progress(
    io,
    global,
    stopped.success
      ? 'teleop ended; the robot was stopped'
      : 'teleop ended; the robot did not confirm the stop',
  );
  return {
    keys: acted,
    pose: await hal.locomotion.getPose(),
    emergencyStopped: hal.safety.isEmergencyStopped(),
    stop: stopped.success
      ? { stopped: true }
      : {
          stopped: false,
          code: stopped.code ?? 'HARDWARE_ERROR',
          error: stopped.error ?? 'the stop failed',
        },
  };
}
