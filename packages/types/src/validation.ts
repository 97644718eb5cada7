import type { z } from 'zod';
import { HalError, toHalError } from './errors.js';
import type { HALMode } from './mode.js';
import { failureResult, successResult } from './result.js';
import type { HALToolResult } from './result.js';
import type { RobotConfig } from './robot-config.js';
import { MOTION_CALLS } from './schemas/call-table.js';
import type { CallTable } from './schemas/call-table.js';
import { createCallSchemas } from './schemas/calls.js';
import type { CallName, CallParams, CallSchemas } from './schemas/calls.js';
import { compileCallSchemas } from './schemas/compiled.js';

function describeValue(value: unknown): string {
  if (typeof value === 'number' || typeof value === 'boolean') return String(value);
  if (typeof value === 'string')
    return JSON.stringify(value.length > 40 ? `${value.slice(0, 40)}...` : value);
  if (value === undefined) return 'nothing';
  if (value === null) return 'null';
  return Array.isArray(value) ? 'an array' : `a ${typeof value}`;
}

function valueAt(input: unknown, path: readonly PropertyKey[]): unknown {
  let current: unknown = input;
  for (const key of path) {
    if (current === null || typeof current !== 'object') return undefined;
    current = (current as Record<PropertyKey, unknown>)[key];
  }
  return current;
}

/**
 * Turns the first zod issue into a HalError whose message names the parameter and the limit.
 * Out-of-range finite numbers are RANGE_EXCEEDED; everything else (NaN, Infinity, wrong type,
 * missing, unknown enum value) is INVALID_PARAMETER.
 */
function issueToError(
  call: CallName,
  schema: z.ZodType,
  args: unknown,
  issue: z.core.$ZodIssue,
): HalError {
  const name = issue.path.map(String).join('.') || 'arguments';
  const received = valueAt(args, issue.path);
  const shape = (schema as unknown as { shape?: Record<string, z.ZodType> }).shape;
  const field = shape?.[String(issue.path[0])];
  const meaning = field?.description ? ` (${field.description})` : '';
  const details = { call, parameter: name, received: describeValue(received) };
  if (issue.code === 'too_big' || issue.code === 'too_small') {
    const limit = Number(issue.code === 'too_big' ? issue.maximum : issue.minimum);
    const inclusive = issue.inclusive !== false;
    const bound =
      issue.code === 'too_big'
        ? `${inclusive ? 'at most' : 'less than'} ${limit}`
        : `${inclusive ? 'at least' : 'greater than'} ${limit}`;
    if (typeof received === 'number') {
      return new HalError(
        'RANGE_EXCEEDED',
        `${call}: "${name}" must be ${bound}, got ${received}${meaning}`,
        { details: { ...details, limit, bound: issue.code === 'too_big' ? 'max' : 'min' } },
      );
    }
    return new HalError('INVALID_PARAMETER', `${call}: "${name}" must be ${bound} long${meaning}`, {
      details: { ...details, limit },
    });
  }
  const why =
    typeof received === 'number' && !Number.isFinite(received)
      ? `must be a finite number, got ${received}`
      : issue.code === 'invalid_value'
        ? `must be one of ${issue.values.map((v) => JSON.stringify(v)).join(', ')}, got ${describeValue(received)}`
        : `is invalid: ${issue.message}, got ${describeValue(received)}`;
  return new HalError('INVALID_PARAMETER', `${call}: "${name}" ${why}${meaning}`, { details });
}

function isThenable<T>(value: T | Promise<T>): value is Promise<T> {
  return (
    (typeof value === 'object' || typeof value === 'function') &&
    value !== null &&
    typeof (value as { then?: unknown }).then === 'function'
  );
}

/** A rejection handler that turns whatever a body threw into a HalError. */
function rejectAsHalError(thrown: unknown): never {
  throw toHalError(thrown);
}

/** What a {@link HalBoundary} needs to know about the HAL it guards. */
export interface HalBoundaryOptions {
  /** Which world the HAL drives, stamped on every result (read each time: a getter may follow it). */
  mode: HALMode;
  /** The robot's current configuration; limits are read from it on every call. */
  config: () => RobotConfig;
  /** Whether the emergency stop is latched. */
  isEmergencyStopped: () => boolean;
  /** Whether the HAL is initialised and reachable. */
  isReady: () => boolean;
  /** The clock results are stamped with, ms. Default `Date.now`. */
  now?: () => number;
  /**
   * An extended call table: its calls beyond the HAL's own are validated with their own
   * parameter schemas (and gated as motion when they are). Default none.
   */
  calls?: CallTable;
  /**
   * Whether parameters are validated here. Default true; false for a HAL that forwards its calls
   * to another HAL (over a link), whose own boundary validates them with the robot's own limits:
   * the limits of a robot elsewhere are not this process's to guess.
   */
  validateParams?: boolean;
}

/** The call schemas of a configuration, and the same compiled by zod (schemas/compiled.ts). */
interface SharedSchemas {
  readonly schemas: CallSchemas;
  readonly compiled: CallSchemas;
}

/** Call schemas by configuration value, shared by every boundary (zod schemas are immutable). */
const sharedSchemas = new Map<string, SharedSchemas>();
const SHARED_SCHEMAS_MAX = 32;

/**
 * The call schemas of a configuration, built once per distinct value: building them costs
 * milliseconds, and each new set runs cold (zod compiles a parser per schema) for its first few
 * hundred calls, which a HAL made anew for the same robot should not pay again. Their compiled
 * clones are built with them, once.
 */
function sharedCallSchemas(config: RobotConfig): SharedSchemas {
  const key = JSON.stringify(config);
  let shared = sharedSchemas.get(key);
  if (shared === undefined) {
    const schemas = createCallSchemas(config);
    shared = { schemas, compiled: compileCallSchemas(schemas) };
    if (sharedSchemas.size >= SHARED_SCHEMAS_MAX) {
      const oldest = sharedSchemas.keys().next().value;
      if (oldest !== undefined) sharedSchemas.delete(oldest);
    }
    sharedSchemas.set(key, shared);
  }
  return shared;
}

/**
 * Safety layer 2, shared by every HAL implementation. Every public call goes through it, with the
 * same rules in the same order: not ready (before `initialize()`, after `cleanup()`): NOT_READY;
 * a motion while the emergency stop is latched: EMERGENCY_STOPPED; bad parameters:
 * INVALID_PARAMETER or RANGE_EXCEEDED naming the parameter and the limit; only then the body,
 * whose capability checks (NOT_IMPLEMENTED) and failures come last.
 * - `call()` serves the calls that answer with a {@link HALToolResult}: it never throws.
 * - `read()` serves the calls that answer with a value (`getPose`, `captureFrame`, `scan`,
 *   `getIMU`, ...): it rejects, always with a {@link HalError}.
 * - `notify()` serves `log`, which returns nothing and never throws: it returns the result for
 *   the HAL to report a refusal through its logger.
 * `isEmergencyStopped()` and `getSafetyStatus()` are exempt: they answer from cached state at any
 * time (before `initialize()`, after `cleanup()`) and never throw, so a safety check never fails.
 */
export class HalBoundary {
  readonly #options: HalBoundaryOptions;
  readonly #now: () => number;
  /** The calls gated by the e-stop: the table's motions and an extended table's. */
  readonly #motion: ReadonlySet<string>;
  #schemasFor: RobotConfig | undefined;
  #shared: SharedSchemas | undefined;

  constructor(options: HalBoundaryOptions) {
    this.#options = options;
    this.#now = options.now ?? Date.now;
    // once, not per call: an extended table would otherwise be searched on every call
    const extended = (options.calls ?? []).filter((entry) => entry.kind === 'motion');
    this.#motion = new Set([...MOTION_CALLS, ...extended.map((entry) => entry.name)]);
  }

  #current(): SharedSchemas {
    const config = this.#options.config();
    if (this.#shared === undefined || this.#schemasFor !== config) {
      this.#shared = sharedCallSchemas(config);
      this.#schemasFor = config;
    }
    return this.#shared;
  }

  /** The call schemas for the robot's current configuration (rebuilt only when it changes). */
  schemas(): CallSchemas {
    return this.#current().schemas;
  }

  /**
   * Validates a call's parameters; throws a HalError that names the parameter and the limit.
   * The call's schema runs compiled by zod (schemas/compiled.ts): the common case takes its
   * generated fast path, and anything that path does not accept, every refusal among them, goes
   * to zod's ordinary parser, which gives the issues.
   */
  validate<N extends CallName>(call: N, args: unknown): CallParams<N> {
    if (this.#options.validateParams === false) return args as CallParams<N>;
    const shared = this.#current();
    if (!Object.hasOwn(shared.compiled, call)) return this.#validateExtended(call, args);
    const parsed = (shared.compiled[call] as z.ZodType).safeParse(args);
    if (!parsed.success) {
      const schema = shared.schemas[call] as z.ZodType;
      const issue = parsed.error.issues[0];
      if (issue === undefined)
        throw new HalError('INVALID_PARAMETER', `${call}: invalid arguments`);
      throw issueToError(call, schema, args, issue);
    }
    return parsed.data as CallParams<N>;
  }

  /** A call of the extended table (`options.calls`); INVALID_PARAMETER for one it lacks. */
  #validateExtended<N extends CallName>(call: N, args: unknown): CallParams<N> {
    const spec = this.#options.calls?.find((entry) => entry.name === call);
    if (spec === undefined) {
      throw new HalError('INVALID_PARAMETER', `unknown HAL call "${call}"`, { details: { call } });
    }
    const schema = spec.paramsSchema(this.#options.config());
    const parsed = schema.safeParse(args);
    if (parsed.success) return parsed.data as CallParams<N>;
    const issue = parsed.error.issues[0];
    if (issue === undefined) throw new HalError('INVALID_PARAMETER', `${call}: invalid arguments`);
    throw issueToError(call, schema, args, issue);
  }

  #isMotion(call: CallName): boolean {
    return this.#motion.has(call);
  }

  /** Throws unless the HAL may take this call now (ready; not emergency-stopped for motion). */
  checkAllowed(call: CallName): void {
    // an e-stop is never refused: before initialize() or after cleanup() it still latches
    if (call !== 'emergencyStop' && !this.#options.isReady()) {
      throw new HalError(
        'NOT_READY',
        `${call}: the HAL is not initialised; call initialize() first`,
      );
    }
    if (this.#isMotion(call) && this.#options.isEmergencyStopped()) {
      throw new HalError(
        'EMERGENCY_STOPPED',
        `${call}: the emergency stop is latched; call safety.resetEmergencyStop() first`,
      );
    }
  }

  /**
   * Guards and validates a value-returning call, then runs it. Rejects with a HalError (anything
   * else the body throws becomes a HARDWARE_ERROR that keeps it as its cause).
   */
  read<N extends CallName, T>(
    call: N,
    args: unknown,
    body: (params: CallParams<N>) => T | Promise<T>,
  ): Promise<T> {
    // not an async function: every call of every HAL comes through here, and an async frame per
    // call was a third of what the boundary allocated; the body's own promise is passed on
    let value: T | Promise<T>;
    try {
      this.checkAllowed(call);
      value = body(this.validate(call, args));
    } catch (thrown) {
      return Promise.reject(toHalError(thrown));
    }
    return isThenable(value)
      ? Promise.resolve(value).then(undefined, rejectAsHalError)
      : Promise.resolve(value);
  }

  /**
   * Guards, validates and runs a call that returns nothing and must never throw (`log`).
   * Returns its result; a refused call has not run its body.
   */
  notify<N extends CallName>(
    call: N,
    args: unknown,
    body: (params: CallParams<N>) => void,
  ): HALToolResult {
    const started = this.#now();
    try {
      this.checkAllowed(call);
      body(this.validate(call, args));
      const finished = this.#now();
      return successResult(this.#options.mode, finished, undefined, finished - started);
    } catch (thrown) {
      const finished = this.#now();
      return failureResult(this.#options.mode, finished, thrown, finished - started);
    }
  }

  /** Guards, validates, runs and times one call; never throws (its promise never rejects). */
  call<N extends CallName>(
    call: N,
    args: unknown,
    body: (params: CallParams<N>) => Promise<Record<string, unknown> | void>,
  ): Promise<HALToolResult> {
    // not an async function, as read() is not
    const started = this.#now();
    let pending: Promise<Record<string, unknown> | void>;
    try {
      this.checkAllowed(call);
      pending = Promise.resolve(body(this.validate(call, args)));
    } catch (thrown) {
      return Promise.resolve(this.#failed(started, thrown));
    }
    return pending.then(
      (data) => this.#succeeded(started, data),
      (thrown: unknown) => this.#failed(started, thrown),
    );
  }

  /**
   * Guards a call that another HAL runs (a forwarding HAL's): the same readiness and e-stop gate
   * as {@link call}, then `body`'s result as the other HAL gave it (its data, timing and codes).
   * Whatever `body` throws becomes a failure result; never rejects.
   */
  forward(call: CallName, body: () => Promise<HALToolResult>): Promise<HALToolResult> {
    const started = this.#now();
    let pending: Promise<HALToolResult>;
    try {
      this.checkAllowed(call);
      pending = body();
    } catch (thrown) {
      return Promise.resolve(this.#failed(started, thrown));
    }
    return pending.then(undefined, (thrown: unknown) => this.#failed(started, thrown));
  }

  #succeeded(started: number, data: Record<string, unknown> | void): HALToolResult {
    try {
      const finished = this.#now();
      return successResult(this.#options.mode, finished, data ?? undefined, finished - started);
    } catch (thrown) {
      return this.#failed(started, thrown);
    }
  }

  #failed(started: number, thrown: unknown): HALToolResult {
    const finished = this.#now();
    return failureResult(this.#options.mode, finished, thrown, finished - started);
  }
}
