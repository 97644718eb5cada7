import { HalError, failureResult } from '@hal/types';
import type { HALMode, HALToolResult } from '@hal/types';
import type { FleetScheduler } from './scheduler.js';

/**
 * Runs one member's call and settles within `timeoutMs` on the scheduler's clock, whatever the
 * member does: its own result, a failed result for anything it throws (a HalError keeps its
 * code), or TIMEOUT. The call itself is not cancelled (a HAL call cannot be), only no longer
 * waited for. Never rejects.
 */
export function callWithTimeout(
  start: () => Promise<HALToolResult>,
  options: { mode: HALMode; device: string; timeoutMs: number; scheduler: FleetScheduler },
): Promise<HALToolResult> {
  const { mode, device, timeoutMs, scheduler } = options;
  const startedAt = scheduler.now();
  return new Promise<HALToolResult>((resolve) => {
    let settled = false;
    const settle = (result: HALToolResult): void => {
      if (settled) return;
      settled = true;
      scheduler.clearTimeout(timer);
      resolve(result);
    };
    const timer = scheduler.setTimeout(() => {
      const error = new HalError(
        'TIMEOUT',
        `device "${device}" did not answer within ${timeoutMs} ms`,
        {
          details: { device, timeoutMs },
        },
      );
      settle(failureResult(mode, Date.now(), error, scheduler.now() - startedAt));
    }, timeoutMs);
    let pending: Promise<HALToolResult>;
    try {
      pending = start();
    } catch (thrown) {
      pending = Promise.reject(thrown);
    }
    pending.then(
      (result) => settle(result),
      (thrown: unknown) =>
        settle(failureResult(mode, Date.now(), thrown, scheduler.now() - startedAt)),
    );
  });
}
