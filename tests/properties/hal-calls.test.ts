import { HAL_CALL_TABLE } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { callArguments, HAL_CALLS, REFUSABLE_CALLS } from './hal-calls.js';

describe('the calls the boundary properties make', () => {
  it('are every call of the call table, or say why one is left out', () => {
    const missed = HAL_CALL_TABLE.filter((spec) => callArguments(spec.name) === undefined);
    expect(missed.map((spec) => spec.name)).toEqual([]);
    const made = HAL_CALL_TABLE.filter((spec) => {
      const args = callArguments(spec.name);
      return args !== undefined && !('exempt' in args);
    });
    expect(HAL_CALLS.map((c) => c.name)).toEqual(
      made.map((spec) => `${spec.subsystem}.${spec.method}`),
    );
    for (const spec of HAL_CALL_TABLE) {
      const args = callArguments(spec.name);
      if (args !== undefined && 'exempt' in args) expect(args.exempt.length).toBeGreaterThan(20);
    }
  });

  it('give bad arguments to every motion call, which the boundary must refuse', () => {
    const motions = HAL_CALL_TABLE.filter((spec) => spec.kind === 'motion').map(
      (spec) => `${spec.subsystem}.${spec.method}`,
    );
    expect(REFUSABLE_CALLS.filter((c) => c.motion).map((c) => c.name)).toEqual(motions);
  });
});
