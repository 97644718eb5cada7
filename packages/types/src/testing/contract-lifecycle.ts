import { describe, expect, it } from 'vitest';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { SafetyStatusSchema } from '../pose.js';
import type { HALToolResult } from '../result.js';
import type { ContractContext } from './contract-expect.js';
import { expectFailedResult, expectRejected, settle } from './contract-expect.js';

type Hal = HardwareAbstractionLayer;

/** Every call that answers with a result, with valid arguments. */
const RESULT_CALLS: Array<[string, (h: Hal) => Promise<HALToolResult>]> = [
  ['drive', (h) => h.locomotion.drive(100, 100, 200)],
  ['moveTo', (h) => h.locomotion.moveTo(0.05, 0, 0)],
  ['rotate', (h) => h.locomotion.rotate('left', 10)],
  ['moveForward', (h) => h.locomotion.moveForward(1)],
  ['moveBackward', (h) => h.locomotion.moveBackward(1)],
  ['stop', (h) => h.locomotion.stop()],
  ['speak', (h) => h.communication.speak('hello')],
  ['setLED', (h) => h.communication.setLED(0, 255, 0, 'solid')],
  ['playSound', (h) => h.communication.playSound('beep')],
  // emergencyStop is left to the e-stop group: a stop is never refused for its circumstances
  ['resetEmergencyStop', (h) => h.safety.resetEmergencyStop()],
];

/** Every call that answers with a value, with valid arguments. */
const READ_CALLS: Array<[string, (h: Hal) => Promise<unknown>]> = [
  ['getPose', (h) => h.locomotion.getPose()],
  ['captureFrame', (h) => h.vision.captureFrame()],
  ['scan', (h) => h.vision.scan('quick')],
  ['getDistanceSensors', (h) => h.vision.getDistanceSensors()],
  ['getLineSensors', (h) => h.vision.getLineSensors()],
  ['getIMU', (h) => h.vision.getIMU()],
];

/** Asserts that every call is refused NOT_READY, and the safety reads still answer. */
async function expectAllNotReady(hal: Hal, when: string): Promise<void> {
  for (const [name, run] of RESULT_CALLS) {
    expectFailedResult(await run(hal), 'NOT_READY', undefined, `${name} ${when}:`);
  }
  for (const [name, run] of READ_CALLS) {
    expectRejected(await settle(() => run(hal)), 'NOT_READY', undefined, `${name} ${when}:`);
  }
  expect(() => hal.communication.log(`a message ${when}`, 'info')).not.toThrow();
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
