import { describe, expect, it } from 'vitest';
import { HAL_CALL_TABLE } from '../schemas/call-table.js';
import type { CallSpec } from '../schemas/call-table.js';
import { boundaryCoverage } from './contract-boundary.js';
import { capabilityCoverage } from './contract-capabilities.js';
import { notReadyRule } from './contract-lifecycle.js';
import { CALL_SAMPLES } from './contract-samples.js';

/** How each group of the suite exercises one call, or why it does not; undefined: it misses it. */
export type CallCoverage = Readonly<Record<string, string | undefined>>;

/** How the e-stop groups exercise `spec`. */
function estopCoverage(spec: CallSpec): string {
  if (spec.kind === 'motion') return 'refused while latched';
  if (spec.tool.safety === 'estop') return 'latched whatever its reason, in every state';
  return 'moves nothing, so the latch does not refuse it';
}

/** How every group of the suite exercises `spec` (see {@link describeCoverageContract}). */
export function callCoverage(spec: CallSpec): CallCoverage {
  const sampled = (CALL_SAMPLES as Readonly<Record<string, unknown>>)[spec.name] !== undefined;
  return {
    lifecycle: sampled ? notReadyRule(spec) : undefined,
    boundary: boundaryCoverage(spec),
    results: sampled ? "answer parsed with the table's schema" : undefined,
    'emergency stop': sampled ? estopCoverage(spec) : undefined,
    capabilities: sampled ? capabilityCoverage(spec) : undefined,
  };
}

/**
 * The suite's check of itself: every call of the call table is exercised by every group, or the
 * group says why not. A call added to the table without its sample (and, if it takes
 * arguments, its bad arguments) fails here, naming the call and the group.
 */
export function describeCoverageContract(): void {
  describe('the suite covers the call table', () => {
    it('exercises every call of the table in every group, or says why it is exempt', () => {
      const missed = HAL_CALL_TABLE.flatMap((spec) =>
        Object.entries(callCoverage(spec))
          .filter(([, how]) => how === undefined)
          .map(([group]) => `${spec.name}: ${group}`),
      );
      expect(missed).toEqual([]);
    });
  });
}
