// Parsers for `hal test hal`'s options: bad values are usage errors before anything is sent.
import { CHECK_GROUPS, SPEC_CAPABILITIES, specCapability } from '@hal/compliance';
import type { CheckGroup, SpecCapability } from '@hal/compliance';
import { integerArg, usageError } from '../values.js';

/** Collects repeated `--capability` values, each one the runner knows. */
export function capabilityArg(
  value: string,
  previous: SpecCapability[] | undefined,
): SpecCapability[] {
  const capability = specCapability(value);
  if (capability === undefined) {
    throw usageError(`"--capability" is one of ${SPEC_CAPABILITIES.join(', ')}, got "${value}"`);
  }
  return [...(previous ?? []), capability];
}

/** Collects repeated `--group` values, each one of the spec's check groups. */
export function groupArg(value: string, previous: CheckGroup[] | undefined): CheckGroup[] {
  const group = CHECK_GROUPS.find((g) => g === value);
  if (group === undefined) {
    throw usageError(`"--group" is one of ${CHECK_GROUPS.join(', ')}, got "${value}"`);
  }
  return [...(previous ?? []), group];
}

export const samplesArg = integerArg('--samples', 1, 10_000);

export function judgeArg(value: string): 'p50' | 'p99' {
  if (value !== 'p50' && value !== 'p99') {
    throw usageError(`"--judge" is p50 or p99, got "${value}"`);
  }
  return value;
}
