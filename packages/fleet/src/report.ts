import type { HALToolResult } from '@hal/types';

/** The three ways a fleet is driven. */
export const FLEET_MODES = ['independent', 'synchronized', 'leader-follower'] as const;

/** One of {@link FLEET_MODES}. */
export type FleetMode = (typeof FLEET_MODES)[number];

/** One member's own outcome of a fleet call. */
export interface MemberResult {
  /** The member's device id. */
  device: string;
  /** The member's own result: its success, or its error, code and details. */
  result: HALToolResult;
  /** When the call was issued to this member, ms on the fleet's clock. */
  issuedAt: number;
}

/** The outcome of one call made to several members at once. */
export interface FleetReport {
  /** The mode that ran the call. */
  mode: FleetMode;
  /** True when every member succeeded. */
  success: boolean;
  /** Every member's own result, in the order the members were given. */
  results: MemberResult[];
  /** Device ids that succeeded. */
  succeeded: string[];
  /** Device ids that failed (each with its own code in `results`). */
  failed: string[];
  /** When the first call was issued, ms on the fleet's clock. */
  startedAt: number;
  /** From the first call's issue to the last member's result, ms. */
  executionTime: number;
}

/** Builds a report from the members' results. */
export function fleetReport(
  mode: FleetMode,
  results: MemberResult[],
  startedAt: number,
  finishedAt: number,
): FleetReport {
  return {
    mode,
    success: results.every((r) => r.result.success),
    results,
    succeeded: results.filter((r) => r.result.success).map((r) => r.device),
    failed: results.filter((r) => !r.result.success).map((r) => r.device),
    startedAt,
    executionTime: Math.max(0, finishedAt - startedAt),
  };
}
