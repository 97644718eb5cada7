import type { z } from 'zod';
import { CAPABILITIES } from '../capabilities.js';
import { HalError } from '../errors.js';
import type { RobotConfig } from '../robot-config.js';
import { createCallSchemas, V1_CALL_SCHEMAS } from './calls.js';
import type { CallName, CallSchemas } from './calls.js';
import { CALL_DATA_SCHEMAS, MOTION_DATA_SCHEMA } from './call-data.js';

/** The subsystem of the HAL a call belongs to. */
export type CallSubsystem = 'locomotion' | 'vision' | 'communication' | 'safety';

/**
 * How a call answers: `motion` and `result` with a `HALToolResult` (motion is refused while the
 * emergency stop is latched), `value` with a value or a rejected HalError, `void` with nothing
 * (it never throws).
 */
export type CallKind = 'motion' | 'result' | 'value' | 'void';

/**
 * Which lane a call travels in where calls are queued: `safety` (stop, e-stop) is never queued
 * behind other traffic and never refused for its arguments; `queue` runs in order; `direct` runs
 * at once beside the queue (reads and logs, which move nothing).
 */
export type CallLane = 'safety' | 'queue' | 'direct';

/**
 * What a motion call does with the robot, for predicting it (the leash, navigation's timeouts)
 * and for choosing a call by what it should do: `forward` and `backward` drive the `distanceCm`
 * parameter straight ahead or back at top speed, `turn` turns in place by `degrees` toward
 * `direction`, `point` turns toward (`x`, `y`) and drives there, `wheels` sets the wheel powers.
 */
export type CallMotion = 'forward' | 'backward' | 'turn' | 'point' | 'wheels';

/** How an LLM tool presents the call. */
export interface CallToolSpec {
  /** Stable, snake_case: agents and transcripts refer to it. */
  readonly name: string;
  /** What the tool does, ahead of the parameter schema's own description. */
  readonly summary: string;
  /** A capability string the robot must offer; absent: every robot has the call. */
  readonly requires?: string;
  /** A stop or an e-stop is never blocked by the leash, approval or the rate limit. */
  readonly safety?: 'stop' | 'estop';
  /** What the tool answers for a call whose own answer is no object (a boolean, nothing). */
  readonly answer?: (value: unknown) => unknown;
}

/** One HAL call, declared once: everything that lists, forwards or serves calls reads this. */
export interface CallSpec {
  /** The call's name, unique across subsystems (e.g. `moveForward`). */
  readonly name: string;
  readonly subsystem: CallSubsystem;
  /** The method on the subsystem (equal to the name for the five-subsystem interface). */
  readonly method: string;
  readonly kind: CallKind;
  /** What the call does with the robot: present exactly for the calls of kind `motion`. */
  readonly motion?: CallMotion;
  readonly lane: CallLane;
  /** Only the controlling client may make it (where a HAL is served to several clients). */
  readonly controllerOnly: boolean;
  /**
   * Answers synchronously from cached state and never throws (`isEmergencyStopped`,
   * `getSafetyStatus`): a forwarding HAL answers it from its own cache.
   */
  readonly cached: boolean;
  /** The parameter names, in argument order. */
  readonly params: readonly string[];
  /** The parameters as one object schema, with limits from a robot configuration. */
  paramsSchema(config: RobotConfig): z.ZodType;
  /**
   * The schema of what a successful call answers: the `data` of its `HALToolResult` (motion and
   * result), its value (value), or nothing (void).
   */
  readonly data: z.ZodType;
  readonly tool: CallToolSpec;
}

/** A list of calls (the HAL's own {@link HAL_CALL_TABLE}, or one extended with more). */
export type CallTable = readonly CallSpec[];

// createCallSchemas builds every schema at once: keep one set per configuration object.
const schemasByConfig = new WeakMap<RobotConfig, CallSchemas>();
function schemasFor(config: RobotConfig): CallSchemas {
  let schemas = schemasByConfig.get(config);
  if (schemas === undefined) {
    schemas = createCallSchemas(config);
    schemasByConfig.set(config, schemas);
  }
  return schemas;
}

type Declared = Omit<
  CallSpec,
  'name' | 'method' | 'params' | 'paramsSchema' | 'data' | 'cached'
> & { readonly cached?: boolean };

function dataSchema(name: CallName, kind: CallKind): z.ZodType {
  const schema = CALL_DATA_SCHEMAS[name] ?? (kind === 'motion' ? MOTION_DATA_SCHEMA : undefined);
  if (schema === undefined) throw new Error(`call-data.ts has no result schema for "${name}"`);
  return schema;
}

function declare(name: CallName, spec: Declared): CallSpec {
  const shape = (V1_CALL_SCHEMAS[name] as unknown as { shape: Record<string, unknown> }).shape;
  return Object.freeze({
    name,
    method: name,
    params: Object.freeze(Object.keys(shape)),
    paramsSchema: (config: RobotConfig) => schemasFor(config)[name],
    data: dataSchema(name, spec.kind),
    ...spec,
    cached: spec.cached ?? false,
    tool: Object.freeze(spec.tool),
  });
}

const DRIVE = CAPABILITIES.differentialDrive;
const driving = {
  subsystem: 'locomotion',
  kind: 'motion',
  lane: 'queue',
  controllerOnly: true,
} as const;
const read = (subsystem: CallSubsystem) =>
  ({ subsystem, kind: 'value', lane: 'direct', controllerOnly: false }) as const;
const command = (subsystem: CallSubsystem) =>
  ({ subsystem, kind: 'result', lane: 'queue', controllerOnly: true }) as const;

/**
 * Every call of the HAL contract, in the order tools are listed. The parameter schemas are the
 * ones of `createCallSchemas`; the result schemas those of `call-data.ts` and `READ_RESULT_SCHEMAS`.
 */
export const HAL_CALL_TABLE: CallTable = Object.freeze([
  declare('moveForward', {
    ...driving,
    motion: 'forward',
    tool: {
      name: 'move_forward',
      requires: DRIVE,
      summary: 'Drive straight ahead (REP-103: +x of the robot) and stop; returns when done.',
    },
  }),
  declare('moveBackward', {
    ...driving,
    motion: 'backward',
    tool: {
      name: 'move_backward',
      requires: DRIVE,
      summary: 'Drive straight back (-x of the robot) and stop; returns when done.',
    },
  }),
  declare('rotate', {
    ...driving,
    motion: 'turn',
    tool: {
      name: 'rotate',
      requires: DRIVE,
      summary:
        'Turn in place; left is counter-clockwise (REP-103 yaw increases). Returns when done.',
    },
  }),
  declare('moveTo', {
    ...driving,
    motion: 'point',
    tool: {
      name: 'move_to',
      requires: DRIVE,
      summary:
        'Drive to a point of the world frame (REP-103: metres, x forward, y left of the start ' +
        'pose): turns toward it in place, then drives straight. Returns on arrival.',
    },
  }),
  declare('drive', {
    ...driving,
    motion: 'wheels',
    tool: {
      name: 'drive',
      requires: DRIVE,
      summary:
        'Set the wheel powers directly (equal powers: straight; opposite: turn in place). Give ' +
        'durationMs, or the wheels keep turning until stop.',
    },
  }),
  declare('stop', {
    subsystem: 'locomotion',
    kind: 'result',
    lane: 'safety',
    controllerOnly: false,
    tool: { name: 'stop', safety: 'stop', summary: 'Stop the wheels now. Always allowed.' },
  }),
  declare('emergencyStop', {
    subsystem: 'safety',
    kind: 'result',
    lane: 'safety',
    controllerOnly: false,
    tool: {
      name: 'emergency_stop',
      safety: 'estop',
      summary:
        'Emergency stop: stops everything and latches; motion is refused until ' +
        'reset_emergency_stop. Always allowed, whatever the reason given.',
    },
  }),
  declare('resetEmergencyStop', {
    ...command('safety'),
    tool: {
      name: 'reset_emergency_stop',
      summary: 'Clear a latched emergency stop so the robot may move again.',
    },
  }),
  declare('getPose', {
    ...read('locomotion'),
    tool: { name: 'get_pose', summary: 'Where the robot is.' },
  }),
  declare('captureFrame', {
    ...read('vision'),
    tool: {
      name: 'capture_frame',
      requires: CAPABILITIES.camera,
      summary: 'Look through the camera: returns the latest frame as a JPEG image.',
    },
  }),
  declare('getDistanceSensors', {
    ...read('vision'),
    tool: {
      name: 'get_distance_sensors',
      requires: CAPABILITIES.rangeSensors,
      summary: 'How far the nearest obstacles are.',
    },
  }),
  declare('scan', {
    ...read('vision'),
    tool: {
      name: 'scan',
      requires: CAPABILITIES.rangeSensors,
      summary: 'Look around for obstacles.',
    },
  }),
  declare('getLineSensors', {
    ...read('vision'),
    tool: {
      name: 'get_line_sensors',
      requires: CAPABILITIES.lineSensors,
      summary: 'Read the floor line sensors.',
    },
  }),
  declare('getIMU', {
    ...read('vision'),
    tool: { name: 'get_imu', summary: 'Read the inertial sensors.' },
  }),
  declare('getSafetyStatus', {
    ...read('safety'),
    cached: true,
    tool: { name: 'get_safety_status', summary: 'Read the safety state.' },
  }),
  declare('isEmergencyStopped', {
    ...read('safety'),
    cached: true,
    tool: {
      name: 'is_emergency_stopped',
      summary: 'Whether the emergency stop is latched.',
      answer: (value) => ({ emergencyStopped: value }),
    },
  }),
  declare('setLED', {
    ...command('communication'),
    tool: {
      name: 'set_led',
      requires: CAPABILITIES.led,
      summary: 'Set the status LED colour and pattern.',
    },
  }),
  declare('speak', {
    ...command('communication'),
    tool: { name: 'speak', requires: CAPABILITIES.speaker, summary: 'Say something aloud.' },
  }),
  declare('playSound', {
    ...command('communication'),
    tool: { name: 'play_sound', requires: CAPABILITIES.sound, summary: 'Play a sound effect.' },
  }),
  declare('log', {
    subsystem: 'communication',
    kind: 'void',
    lane: 'direct',
    controllerOnly: true,
    tool: {
      name: 'log',
      summary: 'Write a message to the robot log.',
      answer: () => ({ logged: true }),
    },
  }),
]);

/** Calls that move the robot: refused while the emergency stop is latched. */
export const MOTION_CALLS: readonly CallName[] = Object.freeze(
  HAL_CALL_TABLE.filter((spec) => spec.kind === 'motion').map((spec) => spec.name as CallName),
);

/** The entry of `name` in `table`, or undefined for a name the table does not have. */
export function findCall(name: string, table: CallTable = HAL_CALL_TABLE): CallSpec | undefined {
  return table.find((spec) => spec.name === name);
}

/**
 * The call of `table` that does `motion` (`backward`: the straight drive back), for code that
 * knows what the robot should do rather than which call does it. Throws when the table has none.
 */
export function motionCall(motion: CallMotion, table: CallTable = HAL_CALL_TABLE): CallSpec {
  const spec = table.find((entry) => entry.motion === motion);
  if (spec === undefined) {
    throw new HalError(
      'INVALID_PARAMETER',
      `the call table has no call whose motion is "${motion}"`,
      {
        details: { motion },
      },
    );
  }
  return spec;
}

/** The table as a map from call name to entry. */
export function callsByName(table: CallTable = HAL_CALL_TABLE): ReadonlyMap<string, CallSpec> {
  return new Map(table.map((spec) => [spec.name, spec]));
}

/** Schemas of the result `data` of every HAL call, for checking answers (tests, clients). */
export const CALL_RESULT_SCHEMAS: Readonly<Record<CallName, z.ZodType>> = Object.freeze(
  Object.fromEntries(HAL_CALL_TABLE.map((spec) => [spec.name, spec.data])) as Record<
    CallName,
    z.ZodType
  >,
);
