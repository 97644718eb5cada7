import { failureResult, HalError, raceTimer } from '@hal/types';
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
  const failed = (thrown: unknown): HALToolResult =>
    failureResult(mode, Date.now(), thrown, scheduler.now() - startedAt);
  // the timer is set before the call starts, as the call may set timers on the same scheduler
  let begin: (work: Promise<HALToolResult>) => void = () => undefined;
  const work = new Promise<HALToolResult>((resolve) => (begin = resolve));
  const answer = raceTimer(
    work,
    timeoutMs,
    () =>
      failed(
        new HalError('TIMEOUT', `device "${device}" did not answer within ${timeoutMs} ms`, {
          details: { device, timeoutMs },
        }),
      ),
    scheduler,
  );
  try {
    begin(start().catch(failed));
  } catch (thrown) {
    begin(Promise.resolve(failed(thrown)));
  }
  return answer;
}
