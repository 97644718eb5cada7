import { HalError } from '../errors.js';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { HAL_CALL_TABLE } from './call-table.js';
import type { CallSpec, CallTable } from './call-table.js';

/**
 * Calls `spec`'s method on `hal` with `args` in order (no validation here: the HAL's own boundary
 * validates them and names the parameter). A synchronous answer or throw becomes a promise.
 * Rejects with NOT_IMPLEMENTED when the HAL has no such subsystem or method.
 */
export function invokeSpec(
  hal: HardwareAbstractionLayer,
  spec: CallSpec,
  args: readonly unknown[],
): Promise<unknown> {
  // not an async function: every served call comes through here, and the method's own promise
  // is passed on rather than wrapped in another frame
  let value: unknown;
  try {
    value = callMethod(hal, spec, args);
  } catch (thrown) {
    return Promise.reject(thrown as Error);
  }
  const answer = Promise.resolve(value);
  return spec.kind === 'void' ? answer.then(() => undefined) : answer;
}

/**
 * Calls `spec`'s method on `hal` with `args` as it is: a synchronous answer stays synchronous and
 * a throw is thrown (for `log`, which answers nothing and must run at once). Throws
 * NOT_IMPLEMENTED when the HAL has no such subsystem or method.
 */
export function callMethod(
  hal: HardwareAbstractionLayer,
  spec: CallSpec,
  args: readonly unknown[],
): unknown {
  const target = (hal as unknown as Record<string, unknown>)[spec.subsystem] as
    Record<string, unknown> | undefined;
  const method = target?.[spec.method];
  if (typeof method !== 'function') {
    throw new HalError('NOT_IMPLEMENTED', `the HAL has no "${spec.subsystem}.${spec.method}"`, {
      details: { call: spec.name },
    });
  }
  return (method as (...a: unknown[]) => unknown).apply(target, args as unknown[]);
}

/**
 * Runs the call `name` of `table` on `hal` with positional `args`; answers its HALToolResult or
 * value. Rejects with INVALID_PARAMETER for a name the table does not have.
 */
export function invokeCall(
  hal: HardwareAbstractionLayer,
  name: string,
  args: readonly unknown[],
  table: CallTable = HAL_CALL_TABLE,
): Promise<unknown> {
  const spec = table.find((entry) => entry.name === name);
  if (spec === undefined) {
    return Promise.reject(
      new HalError('INVALID_PARAMETER', `unknown HAL call "${name}"`, { details: { call: name } }),
    );
  }
  return invokeSpec(hal, spec, args);
}

/** The positional arguments of `spec` from named ones (`{ distanceCm: 10 }` -> `[10]`). */
export function argsFromObject(
  spec: CallSpec,
  named: Readonly<Record<string, unknown>>,
): unknown[] {
  const args = spec.params.map((param) => named[param]);
  while (args.length > 0 && args[args.length - 1] === undefined) args.pop();
  return args;
}

/** The named arguments of `spec` from positional ones (`[10]` -> `{ distanceCm: 10 }`). */
export function objectFromArgs(spec: CallSpec, args: readonly unknown[]): Record<string, unknown> {
  return Object.fromEntries(spec.params.map((param, i) => [param, args[i]]));
}
