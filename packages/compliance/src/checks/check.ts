import type { RunContext } from '../context.js';
import type { CheckGroup, Measured } from '../report.js';
import type { LatencyClass, SpecCapability } from '../spec.js';

/** What a check found. */
export interface Verdict {
  /** 'skip': there was nothing to judge, because the checks that bring it were not run. */
  status: 'pass' | 'fail' | 'skip';
  reason: string;
  measured?: Measured;
  latencyClass?: LatencyClass;
  rateHz?: number;
}

/** One check of the runner. */
export interface Check {
  capability: SpecCapability;
  group: CheckGroup;
  /** Short id within its capability and group, e.g. `out-of-range`. */
  name: string;
  title: string;
  /**
   * 'announced' (default): runs when the device announces the capability, else it is skipped;
   * 'unannounced': runs only when it does not (the capability must then be honestly absent).
   */
  when?: 'announced' | 'unannounced';
  /** Runs only when the option is asked for (`mdns: true`); otherwise it is not part of the run. */
  onlyWith?: 'mdns';
  run(ctx: RunContext): Promise<Verdict>;
}

export const pass = (reason: string, extra: Omit<Verdict, 'status' | 'reason'> = {}): Verdict => ({
  status: 'pass',
  reason,
  ...extra,
});

export const fail = (reason: string, extra: Omit<Verdict, 'status' | 'reason'> = {}): Verdict => ({
  status: 'fail',
  reason,
  ...extra,
});

export const skip = (reason: string): Verdict => ({ status: 'skip', reason });

/** Waits `ms` (the one `delay` of @hal/types). */
export { delay as sleep } from '@hal/types';
