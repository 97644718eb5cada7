import { expect } from 'vitest';
import { isHalError } from '../errors.js';
import type { HalErrorCode } from '../errors.js';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { HALToolResultSchema } from '../result.js';
import type { HALToolResult } from '../result.js';

/** What a contract group needs from the suite that runs it. */
export interface ContractContext {
  /** The HAL under test (a fresh one for every test, not initialised). */
  hal(): HardwareAbstractionLayer;
  /** Initialises the HAL under test and returns it. */
  ready(): Promise<HardwareAbstractionLayer>;
  /** Timeout of each test, ms. */
  timeout: number;
}

/** Asserts a well-formed failed result with `code`, naming `parameter` when one is given. */
export function expectFailedResult(
  result: HALToolResult,
  code: HalErrorCode,
  parameter?: string,
  label = '',
): void {
  const shown = `${label} ${JSON.stringify(result)}`;
  expect(HALToolResultSchema.safeParse(result).success, shown).toBe(true);
  expect(result.success, shown).toBe(false);
  expect(result.code, shown).toBe(code);
  if (parameter !== undefined) expect(result.error, shown).toContain(`"${parameter}"`);
}

/** Asserts a well-formed successful result. */
export function expectSucceeded(result: HALToolResult, label = ''): void {
  const shown = `${label} ${JSON.stringify(result)}`;
  expect(HALToolResultSchema.safeParse(result).success, shown).toBe(true);
  expect(result.success, shown).toBe(true);
}

/** What a value-returning call did: resolved with a value, or rejected with an error. */
export type Settled<T> = { value: T } | { error: unknown };

/** Runs a value-returning call without letting it throw, synchronously or not. */
export async function settle<T>(call: () => Promise<T>): Promise<Settled<T>> {
  try {
    return { value: await call() };
  } catch (error) {
    return { error };
  }
}

/** Asserts that a value-returning call rejected with a HalError of `code`, naming `parameter`. */
export function expectRejected(
  outcome: Settled<unknown>,
  code: HalErrorCode,
  parameter?: string,
  label = '',
): void {
  expect('error' in outcome, `${label} resolved instead of rejecting`).toBe(true);
  if (!('error' in outcome)) return;
  const error = outcome.error;
  expect(isHalError(error), `${label} rejected with ${String(error)}, not a HalError`).toBe(true);
  if (!isHalError(error)) return;
  expect(error.code, `${label} ${error.message}`).toBe(code);
  if (parameter !== undefined) expect(error.message, label).toContain(`"${parameter}"`);
}
