import { describe, expect, it } from 'vitest';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { SafetyStatusSchema } from '../pose.js';
import type { HALToolResult } from '../result.js';
import type { CallSpec } from '../schemas/call-table.js';
import { callMethod, invokeSpec } from '../schemas/invoke-call.js';
import type { ContractContext } from './contract-expect.js';
import { expectFailedResult, expectRejected, settle } from './contract-expect.js';
import { sampledCalls } from './contract-samples.js';

type Hal = HardwareAbstractionLayer;

/**
 * What each call must do before `initialize()` and after `cleanup()`, read from its table entry:
 * a result call fails NOT_READY, a value call rejects NOT_READY, a cached read answers (a safety
 * check cannot fail), `log` (void) never throws, and the e-stop is left to the e-stop group (it
 * is never refused, whatever the HAL's state).
 */
export type NotReadyRule = 'fails' | 'rejects' | 'answers' | 'never throws' | 'never refused';

/** The rule of `spec` before `initialize()` and after `cleanup()` (see {@link NotReadyRule}). */
export function notReadyRule(spec: CallSpec): NotReadyRule {
  if (spec.tool.safety === 'estop') return 'never refused';
  switch (spec.kind) {
    case 'motion':
    case 'result':
      return 'fails';
    case 'value':
      return spec.cached ? 'answers' : 'rejects';
    case 'void':
      return 'never throws';
  }
}

/** Asserts that every call is refused NOT_READY, and the safety reads still answer. */
async function expectAllNotReady(hal: Hal, when: string): Promise<void> {
  for (const [spec, args] of sampledCalls()) {
    const label = `${spec.name} ${when}:`;
    switch (notReadyRule(spec)) {
      case 'fails':
        expectFailedResult(
          (await invokeSpec(hal, spec, args)) as HALToolResult,
          'NOT_READY',
          undefined,
          label,
        );
        break;
      case 'rejects':
        expectRejected(
          await settle(() => invokeSpec(hal, spec, args)),
          'NOT_READY',
          undefined,
          label,
        );
        break;
      case 'answers':
      case 'never throws':
        expect(() => callMethod(hal, spec, args), label).not.toThrow();
        break;
      case 'never refused':
        break;
    }
  }
  expect(() => hal.communication.log(`a message ${when}`, 'bogus' as 'info')).not.toThrow();
  const stopped = hal.safety.isEmergencyStopped();
  expect(typeof stopped).toBe('boolean');
  expect(SafetyStatusSchema.parse(hal.safety.getSafetyStatus()).emergencyStopped).toBe(stopped);
}

/**
 * Readiness, the same on every HAL: before `initialize()` and after `cleanup()` every call is
 * refused NOT_READY (a result, or a rejection with a HalError), and starts nothing; `log` never
 * throws; the safety reads answer from cached state.
 */
export function describeLifecycleContract(ctx: ContractContext): void {
  const { timeout } = ctx;

  describe('every call before initialize() and after cleanup()', () => {
    it(
      'refuses every call with NOT_READY before initialize(), and the safety reads answer',
      { timeout },
      async () => {
        const hal = ctx.hal();
        await expectAllNotReady(hal, 'before initialize()');
        expect(hal.safety.isEmergencyStopped()).toBe(false);
        expect(hal.isReady()).toBe(false);
      },
    );

    it(
      'refuses every call with NOT_READY after cleanup(), and stays not ready',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        await hal.cleanup();
        await expectAllNotReady(hal, 'after cleanup()');
        expect(hal.isReady()).toBe(false);
      },
    );

    it('works again when initialised after cleanup()', { timeout }, async () => {
      const hal = await ctx.ready();
      await hal.cleanup();
      await hal.initialize();
      expect(hal.isReady()).toBe(true);
      const pose = await hal.locomotion.getPose();
      expect(Number.isFinite(pose.position.x)).toBe(true);
      expect((await hal.locomotion.stop()).success).toBe(true);
    });
  });
}
