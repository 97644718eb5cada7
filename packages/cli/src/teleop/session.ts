// Keyboard driving: each key becomes one HAL call, made in order; a live pose line on stderr.
// A drive key sets an open-ended drive that runs until the next key (space stops it).
import type { HALToolResult, HardwareAbstractionLayer, Pose } from '@hal/types';
import { emit, progress } from '../io.js';
import type { CliIO, GlobalOptions } from '../io.js';
import { poseText } from '../pose-text.js';
import { sleep } from '../wait.js';
import { parseKeys } from './keys.js';
import type { TeleopKey } from './keys.js';
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
  pose: Pose;
  emergencyStopped: boolean;
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
 * input or an abort of `io.signal`; then stops the robot.
 */
export async function runTeleop(
  hal: HardwareAbstractionLayer,
  stdin: TerminalInput,
  io: CliIO,
  global: GlobalOptions,
  options: TeleopOptions,
): Promise<TeleopSummary> {
  const pending: TeleopKey[] = [];
  const acted: TeleopKey[] = [];
  let wake: (() => void) | undefined;
  let ended = false;
  const end = (): void => {
    ended = true;
    wake?.();
  };
  const onData = (chunk: Buffer | string): void => {
    pending.push(...parseKeys(typeof chunk === 'string' ? chunk : chunk.toString('latin1')));
    wake?.();
  };
  stdin.on('data', onData);
  stdin.once('end', end);
  io.signal.addEventListener('abort', end, { once: true });

  const lineDone = new AbortController();
  let status = 'ready';
  const poseLine = (async () => {
    while (!lineDone.signal.aborted && !global.json) {
      const pose = await hal.locomotion.getPose().catch(() => undefined);
      const estop = hal.safety.isEmergencyStopped() ? '  E-STOP' : '';
      if (pose !== undefined && !lineDone.signal.aborted) {
        io.err(`\r\x1b[K${poseText(pose)}  ${status}${estop}`);
      }
      await sleep(POSE_LINE_MS, lineDone.signal);
    }
  })();

  try {
    for (;;) {
      if (io.signal.aborted) break;
      const key = pending.shift();
      if (key === undefined) {
        if (ended) break;
        await new Promise<void>((resolve) => (wake = resolve));
        wake = undefined;
        continue;
      }
      if (key === 'quit') break;
      acted.push(key);
      const result = await callFor(hal, key, options);
      status = result.success ? key : `${key} refused: ${result.code ?? 'FAILED'}`;
      if (global.json) emit(io, global, { key, result }, () => '');
    }
  } finally {
    stdin.off('data', onData);
    stdin.off('end', end);
    io.signal.removeEventListener('abort', end);
    lineDone.abort();
    await poseLine;
    if (!global.json) io.err('\n');
    await hal.locomotion.stop().catch(() => undefined);
  }
  progress(io, global, 'teleop ended; the robot was stopped');
  return {
    keys: acted,
    pose: await hal.locomotion.getPose(),
    emergencyStopped: hal.safety.isEmergencyStopped(),
  };
}
