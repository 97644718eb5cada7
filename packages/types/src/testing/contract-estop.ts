import { describe, expect, it } from 'vitest';
import { delay } from '../vocabulary/time.js';
import { ESTOP_REASON_MAX_BYTES, sanitizeEstopReason } from '../estop-reason.js';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { PoseSchema, SafetyStatusSchema } from '../pose.js';
import { HALToolResultSchema } from '../result.js';
import type { HALToolResult } from '../result.js';

/** Reasons an e-stop must take without refusing: each is stored sanitized. */
const AWKWARD_REASONS: ReadonlyArray<[string, unknown]> = [
  ['201 characters', 'x'.repeat(201)],
  ['a number', 42],
  ['undefined', undefined],
  ['an object', {}],
  ['null', null],
  ['control characters', '\u0000bumper\r\nhit\u0007'.repeat(40)],
  ['200 control characters', '\u0001'.repeat(200)],
  ['a lone surrogate', 'cliff \ud800 ahead'],
  ['quotes and backslashes', '"\\'.repeat(100)],
  ['multi-byte text', 'стоп'.repeat(30)],
];

function expectResult(result: HALToolResult, success: boolean): void {
  expect(HALToolResultSchema.safeParse(result).success, JSON.stringify(result)).toBe(true);
  expect(result.success, JSON.stringify(result)).toBe(success);
}

/**
 * The e-stop part of the contract: an emergency stop is never refused (whatever its argument,
 * before `initialize()`, after `cleanup()`), always latches, stores its reason sanitized by
 * {@link sanitizeEstopReason}, and only a reset clears it.
 */
export function describeEstopContract(
  getHal: () => HardwareAbstractionLayer,
  timeout: number,
): void {
  describe('emergency stop is never refused', () => {
    it(
      'latches whatever the reason, stores it sanitized, refuses motion, and resets',
      { timeout },
      async () => {
        const hal = getHal();
        await hal.initialize();
        for (const [what, reason] of AWKWARD_REASONS) {
          const stored = sanitizeEstopReason(reason);
          expect(new TextEncoder().encode(stored).length).toBeLessThanOrEqual(
            ESTOP_REASON_MAX_BYTES,
          );
          const result = await hal.safety.emergencyStop(reason as string);
          expectResult(result, true);
          if (result.data?.['reason'] !== undefined) {
            expect(result.data['reason'], what).toBe(stored);
          }
          expect(hal.safety.isEmergencyStopped(), what).toBe(true);
          const status = SafetyStatusSchema.parse(hal.safety.getSafetyStatus());
          expect(status.emergencyStopReason, what).toBe(stored);
          const refused = await hal.locomotion.moveForward(5);
          expect(refused.code, what).toBe('EMERGENCY_STOPPED');
          expectResult(await hal.safety.resetEmergencyStop(), true);
          expect(hal.safety.isEmergencyStopped(), what).toBe(false);
        }
        expectResult(await hal.locomotion.moveForward(1), true);
      },
    );

    it(
      'latches before initialize(): motion is refused after it until the stop is reset',
      { timeout },
      async () => {
        const hal = getHal();
        expectResult(await hal.safety.emergencyStop('before start'), true);
        expect(hal.safety.isEmergencyStopped()).toBe(true);
        await hal.initialize();
        expect(hal.safety.isEmergencyStopped()).toBe(true);
        expect((await hal.locomotion.moveForward(5)).code).toBe('EMERGENCY_STOPPED');
        expectResult(await hal.safety.resetEmergencyStop(), true);
        expect(hal.safety.isEmergencyStopped()).toBe(false);
        expectResult(await hal.locomotion.moveForward(1), true);
      },
    );

    it('latches after cleanup() too', { timeout }, async () => {
      const hal = getHal();
      await hal.initialize();
      await hal.cleanup();
      expectResult(await hal.safety.emergencyStop(7 as unknown as string), true);
      expect(hal.safety.isEmergencyStopped()).toBe(true);
    });

    it(
      'ends a motion under way: it reports EMERGENCY_STOPPED (or had finished) and nothing moves after',
      { timeout },
      async () => {
        const hal = getHal();
        await hal.initialize();
        const moving = hal.locomotion.moveForward(20);
        expectResult(await hal.safety.emergencyStop('mid-move'), true);
        const move = await moving;
        expect(HALToolResultSchema.safeParse(move).success).toBe(true);
        if (!move.success) expect(move.code).toBe('EMERGENCY_STOPPED');
        const at = PoseSchema.parse(await hal.locomotion.getPose()).position;
        await delay(50);
        expect(PoseSchema.parse(await hal.locomotion.getPose()).position).toEqual(at);
        expect(hal.safety.isEmergencyStopped()).toBe(true);
      },
    );
  });
}
