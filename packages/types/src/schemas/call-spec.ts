import type { z } from 'zod';
import type { RobotConfig } from '../robot-config.js';
import { paramParts } from './param-parts.js';
import type { ParamParts } from './param-parts.js';

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

/** A list of calls (the HAL's own table, or one extended with more). */
export type CallTable = readonly CallSpec[];

/**
 * One call as a table declares it, under its name: what a {@link CallSpec} says, with the
 * parameter schema written from a configuration's {@link ParamParts} (its parameter names are
 * read from it).
 */
export interface CallDeclaration {
  readonly subsystem: CallSubsystem;
  readonly kind: CallKind;
  readonly motion?: CallMotion;
  readonly lane: CallLane;
  readonly controllerOnly: boolean;
  readonly cached?: boolean;
  params(parts: ParamParts): z.ZodType;
  readonly data: z.ZodType;
  readonly tool: CallToolSpec;
}

// One set of parts per configuration object, shared by every call.
const partsByConfig = new WeakMap<RobotConfig, ParamParts>();
function partsFor(config: RobotConfig): ParamParts {
  let parts = partsByConfig.get(config);
  if (parts === undefined) {
    parts = paramParts(config);
    partsByConfig.set(config, parts);
  }
  return parts;
}

function specOf(name: string, declared: CallDeclaration, reference: RobotConfig): CallSpec {
  // one schema per configuration object, so a call's schema is the same object on every ask
  const schemas = new WeakMap<RobotConfig, z.ZodType>();
  const paramsSchema = (config: RobotConfig): z.ZodType => {
    let schema = schemas.get(config);
    if (schema === undefined) {
      schema = declared.params(partsFor(config));
      schemas.set(config, schema);
    }
    return schema;
  };
  const shape = (paramsSchema(reference) as unknown as { shape: Record<string, unknown> }).shape;
  const { params: _params, cached, tool, ...rest } = declared;
  return Object.freeze({
    name,
    method: name,
    ...rest,
    cached: cached ?? false,
    params: Object.freeze(Object.keys(shape)),
    paramsSchema,
    tool: Object.freeze(tool),
  });
}

/**
 * The table of `declarations`, in their order; each parameter schema is an object schema whose
 * keys, read with the `reference` configuration, are the call's parameters in argument order.
 */
export function tableOf(
  declarations: Readonly<Record<string, CallDeclaration>>,
  reference: RobotConfig,
): CallTable {
  return Object.freeze(
    Object.entries(declarations).map(([name, declared]) => specOf(name, declared, reference)),
  );
}
