import type { LatencyClass, SpecCapability } from './spec.js';

/** The spec's check groups ("Tests verify: ..."), in the order the spec lists them. */
export const CHECK_GROUPS = ['format', 'timing', 'errors', 'capability', 'state'] as const;
export type CheckGroup = (typeof CHECK_GROUPS)[number];

export type CheckStatus = 'pass' | 'fail' | 'skip';

/** Latencies (or stream intervals) measured by a timing check, ms. */
export interface Measured {
  samples: number;
  p50Ms: number;
  p99Ms: number;
  maxMs: number;
}

/** One check's outcome. */
export interface CheckResult {
  /** Stable id, e.g. `motor.differential/errors/out-of-range`. */
  id: string;
  capability: SpecCapability;
  group: CheckGroup;
  /** What was checked, as a sentence. */
  title: string;
  status: CheckStatus;
  /** Why it failed or was skipped; for a pass, what was seen. */
  reason: string;
  /** Latencies for timing checks. */
  measured?: Measured;
  /** The spec class the latency was held to. */
  latencyClass?: LatencyClass;
  /** A stream rate, Hz, for stream checks. */
  rateHz?: number;
  durationMs: number;
}

export interface ComplianceReport {
  /** The device id the device reported (its envelopes' `device_id`). */
  deviceId: string;
  /** The `--device` asked for; undefined: the spec's default device (bare subjects). */
  addressed: string | undefined;
  deviceType: string;
  mode: string;
  /** The capability strings the device announced. */
  caps: string[];
  /** The spec capabilities checked. */
  capabilities: SpecCapability[];
  /** The check groups run (all five unless `groups` chose fewer). */
  groups: CheckGroup[];
  /** Which latency percentile was held to the class limits. */
  judge: 'p50' | 'p99';
  checks: CheckResult[];
  summary: { passed: number; failed: number; skipped: number };
  /** True when no check failed (and the run was not aborted). */
  ok: boolean;
  /** The run was aborted before every check ran. */
  aborted: boolean;
  startedAt: string;
  durationMs: number;
}
