// The motions and safety calls `hal drive` can make, checked against the HAL's own call schemas
// (V1 limits) before anything is sent: a bad number is a USAGE error, never a motor command.
import { InvalidArgumentError } from 'commander';
import { V1_CALL_SCHEMAS } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { CliError } from '../cli-error.js';

export type DriveAction =
  | { kind: 'forward'; metres: number }
  | { kind: 'turn'; degrees: number }
  | { kind: 'move-to'; x: number; y: number; speed?: number }
  | { kind: 'wheels'; left: number; right: number; durationMs?: number }
  | { kind: 'stop' }
  | { kind: 'estop'; reason?: string }
  | { kind: 'reset-estop' };

/** A command-line number: finite, nothing else (so "1e3" is fine and "12abc", "NaN" are not). */
export function numberArg(name: string) {
  return (value: string): number => {
    const n = Number(value);
    if (value.trim() === '' || !Number.isFinite(n)) {
      throw new InvalidArgumentError(`${name} must be a finite number, got "${value}"`);
    }
    return n;
  };
}

/** The part of a zod schema used here (so this package needs no zod of its own). */
interface Checker {
  safeParse(
    value: unknown,
  ):
    | { success: true }
    | { success: false; error: { issues: { path: PropertyKey[]; message: string }[] } };
}

function check(schema: Checker, params: unknown, what: string): void {
  const parsed = schema.safeParse(params);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    const field = issue?.path.map(String).join('.') ?? '';
    throw new CliError(
      'USAGE',
      `${what}: ${field === '' ? '' : `${field} `}${issue?.message ?? 'invalid'}`,
    );
  }
}

/** Refuses an action the robot's limits would refuse (USAGE), before connecting. */
export function checkAction(action: DriveAction): void {
  const s = V1_CALL_SCHEMAS;
  switch (action.kind) {
    case 'forward':
      if (action.metres === 0) throw new CliError('USAGE', 'forward: the distance must not be 0');
      check(s.moveForward, { distanceCm: Math.abs(action.metres) * 100 }, 'forward (sent in cm)');
      return;
    case 'turn':
      if (action.degrees === 0) throw new CliError('USAGE', 'turn: the angle must not be 0');
      check(s.rotate, { direction: 'left', degrees: Math.abs(action.degrees) }, 'turn');
      return;
    case 'move-to':
      check(s.moveTo, { x: action.x, y: action.y, z: 0, speed: action.speed }, 'move-to');
      return;
    case 'wheels':
      check(s.drive, action, 'wheels');
      return;
    case 'estop':
      check(s.emergencyStop, { reason: action.reason ?? '' }, 'estop');
      return;
    default:
      return;
  }
}

/** True for the actions that move the robot (and so show live pose, and stop on Ctrl-C). */
export function isMotion(action: DriveAction): boolean {
  return ['forward', 'turn', 'move-to', 'wheels'].includes(action.kind);
}

/** Makes the HAL call for `action`. */
export function callFor(
  hal: HardwareAbstractionLayer,
  action: DriveAction,
): Promise<HALToolResult> {
  const loco = hal.locomotion;
  switch (action.kind) {
    case 'forward':
      return action.metres > 0
        ? loco.moveForward(action.metres * 100)
        : loco.moveBackward(-action.metres * 100);
    case 'turn':
      // REP-103: positive degrees turn counter-clockwise (left)
      return loco.rotate(action.degrees > 0 ? 'left' : 'right', Math.abs(action.degrees));
    case 'move-to':
      return loco.moveTo(action.x, action.y, 0, action.speed);
    case 'wheels':
      return loco.drive(action.left, action.right, action.durationMs);
    case 'stop':
      return loco.stop();
    case 'estop':
      return hal.safety.emergencyStop(action.reason);
    case 'reset-estop':
      return hal.safety.resetEmergencyStop();
  }
}

/** `forward 0.5 m`, for messages. */
export function actionText(action: DriveAction): string {
  switch (action.kind) {
    case 'forward':
      return `forward ${action.metres} m`;
    case 'turn':
      return `turn ${action.degrees}°`;
    case 'move-to':
      return `move-to (${action.x}, ${action.y})`;
    case 'wheels':
      return `wheels ${action.left} ${action.right}${action.durationMs === undefined ? '' : ` for ${action.durationMs} ms`}`;
    case 'stop':
      return 'stop';
    case 'estop':
      return 'emergency stop';
    case 'reset-estop':
      return 'reset emergency stop';
  }
}
