// The motions and safety calls `hal drive` can make, checked against the HAL's own call schemas
// (V1 limits) before anything is sent: a bad number is a USAGE error, never a motor command.
import { V1_ROBOT, argsFromObject, findCall, invokeSpec, motionCall } from '@hal/types';
import type { CallSpec, HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { CliError } from '../cli-error.js';

export type DriveAction =
  | { kind: 'forward'; metres: number }
  | { kind: 'turn'; degrees: number }
  | { kind: 'move-to'; x: number; y: number; speed?: number }
  | { kind: 'wheels'; left: number; right: number; durationMs?: number }
  | { kind: 'stop' }
  | { kind: 'estop'; reason?: string }
  | { kind: 'reset-estop' };

/** One issue of a zod schema, as far as this file reads it. */
interface Issue {
  path: PropertyKey[];
  message: string;
  code?: string;
  minimum?: unknown;
  maximum?: unknown;
  inclusive?: boolean;
}

/** The part of a zod schema used here (so this package needs no zod of its own). */
interface Checker {
  safeParse(value: unknown): { success: true } | { success: false; error: { issues: Issue[] } };
}

/**
 * How a call's parameter reads on the command line: its name there, the unit the user typed, and
 * the factor from the call's unit to that one (`distanceCm` is typed in metres: 0.01).
 */
interface Typed {
  name: string;
  unit: string;
  factor: number;
}

const TYPED: Readonly<Record<string, Typed>> = {
  distanceCm: { name: 'distance', unit: ' m', factor: 0.01 },
  degrees: { name: 'angle', unit: '°', factor: 1 },
  x: { name: 'x', unit: ' m', factor: 1 },
  y: { name: 'y', unit: ' m', factor: 1 },
  speed: { name: 'speed', unit: ' m/s', factor: 1 },
  left: { name: 'left power', unit: '', factor: 1 },
  right: { name: 'right power', unit: '', factor: 1 },
  durationMs: { name: 'duration', unit: ' ms', factor: 1 },
  reason: { name: 'reason', unit: '', factor: 1 },
};

/** A number as people read it: at most 3 decimals, no trailing zeros (1.884, not 1.8840000). */
function figure(n: number): string {
  return String(Number(n.toFixed(3)));
}

/**
 * The issue in the user's terms: "distance 5 m is above the limit 1.884 m" for a range limit
 * (the value as typed, the limit converted to its unit); zod's own text for anything else.
 */
function issueText(issue: Issue, typedValue: number | undefined, signed: boolean): string {
  const field = issue.path.map(String).join('.');
  const typed = TYPED[field];
  const limit = issue.code === 'too_big' ? issue.maximum : issue.minimum;
  const isRange = issue.code === 'too_big' || issue.code === 'too_small';
  if (typed === undefined || !isRange || typeof limit !== 'number' || typedValue === undefined) {
    return `${field === '' ? '' : `${field} `}${issue.message}`;
  }
  // forward and turn check the size of a signed value: a refused -5 m is below -1.884 m
  const mirrored = signed && typedValue < 0;
  const above = (issue.code === 'too_big') !== mirrored;
  const bound = figure((mirrored ? -limit : limit) * typed.factor);
  const relation =
    issue.inclusive === false
      ? above
        ? 'must be below'
        : 'must be above'
      : above
        ? 'is above the limit'
        : 'is below the limit';
  return `${typed.name} ${figure(typedValue)}${typed.unit} ${relation} ${bound}${typed.unit}`;
}

function check(
  schema: Checker,
  params: Record<string, unknown>,
  what: string,
  /** The values as typed where the call is sent their size (`forward -5`: distanceCm 500). */
  typedValues: Readonly<Record<string, number | undefined>> = {},
): void {
  const parsed = schema.safeParse(params);
  if (!parsed.success) {
    const issue = parsed.error.issues[0];
    if (issue === undefined) throw new CliError('USAGE', `${what}: invalid`);
    const field = issue.path.map(String).join('.');
    const signed = typedValues[field] !== undefined;
    const value = typedValues[field] ?? params[field];
    throw new CliError(
      'USAGE',
      `${what}: ${issueText(issue, typeof value === 'number' ? value : undefined, signed)}`,
    );
  }
}

/**
 * The HAL call an action makes, with its parameters by name, and the values as typed where the
 * call is sent their size (`forward -5`: the drive back with distanceCm 500; messages speak of
 * -5 m).
 */
interface ActionCall {
  call: CallSpec;
  params: Record<string, unknown>;
  typed?: Readonly<Record<string, number>>;
}

/** The call of the HAL's table named `name`, which this file knows it has. */
function tableCall(name: string): CallSpec {
  const spec = findCall(name);
  if (spec === undefined) throw new Error(`the HAL's call table has no "${name}"`);
  return spec;
}

function actionCall(action: DriveAction): ActionCall {
  switch (action.kind) {
    case 'forward':
      // the call takes centimetres; the message speaks of the metres that were typed
      return {
        call: motionCall(action.metres > 0 ? 'forward' : 'backward'),
        params: { distanceCm: Math.abs(action.metres) * 100 },
        typed: { distanceCm: action.metres },
      };
    case 'turn':
      // REP-103: positive degrees turn counter-clockwise (left)
      return {
        call: motionCall('turn'),
        params: {
          direction: action.degrees > 0 ? 'left' : 'right',
          degrees: Math.abs(action.degrees),
        },
        typed: { degrees: action.degrees },
      };
    case 'move-to':
      return {
        call: motionCall('point'),
        params: { x: action.x, y: action.y, z: 0, speed: action.speed },
      };
    case 'wheels':
      return {
        call: motionCall('wheels'),
        params: { left: action.left, right: action.right, durationMs: action.durationMs },
      };
    case 'stop':
      return { call: tableCall('stop'), params: {} };
    case 'estop':
      return { call: tableCall('emergencyStop'), params: { reason: action.reason } };
    case 'reset-estop':
      return { call: tableCall('resetEmergencyStop'), params: {} };
  }
}

/** Refuses an action the robot's limits would refuse (USAGE), before connecting. */
export function checkAction(action: DriveAction): void {
  if (action.kind === 'forward' && action.metres === 0) {
    throw new CliError('USAGE', 'forward: the distance must not be 0');
  }
  if (action.kind === 'turn' && action.degrees === 0) {
    throw new CliError('USAGE', 'turn: the angle must not be 0');
  }
  const { call, params, typed } = actionCall(action);
  check(call.paramsSchema(V1_ROBOT) as Checker, params, action.kind, typed);
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
  const { call, params } = actionCall(action);
  return invokeSpec(hal, call, argsFromObject(call, params)) as Promise<HALToolResult>;
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
