import { describe, expect, it } from 'vitest';
import { HalError } from './errors.js';
import { HALToolResultSchema } from './result.js';
import { maxDistancePerCommandCm, robotConfig, V1_ROBOT } from './robot-config.js';
import type { RobotConfig } from './robot-config.js';
import { HalBoundary } from './validation.js';

function boundary(state: { ready?: boolean; estop?: boolean; config?: RobotConfig } = {}) {
  let t = 1000;
  const b = new HalBoundary({
    mode: 'simulation',
    config: () => state.config ?? V1_ROBOT,
    isEmergencyStopped: () => state.estop ?? false,
    isReady: () => state.ready ?? true,
    now: () => (t += 5),
  });
  return b;
}

describe('HalBoundary', () => {
  describe('#validate', () => {
    it('passes valid parameters through, typed', () => {
      expect(boundary().validate('moveForward', { distanceCm: 10 })).toEqual({ distanceCm: 10 });
      expect(boundary().validate('rotate', { direction: 'left', degrees: 90 })).toEqual({
        direction: 'left',
        degrees: 90,
      });
    });

    it.each([
      ['NaN', Number.NaN],
      ['Infinity', Number.POSITIVE_INFINITY],
      ['-Infinity', Number.NEGATIVE_INFINITY],
      ['a string', '10'],
      ['null', null],
      ['nothing', undefined],
    ])('refuses %s with INVALID_PARAMETER naming the parameter', (_label, value) => {
      const error = (() => {
        try {
          boundary().validate('moveForward', { distanceCm: value });
        } catch (e) {
          return e;
        }
        return undefined;
      })();
      expect(error).toBeInstanceOf(HalError);
      expect((error as HalError).code).toBe('INVALID_PARAMETER');
      expect((error as HalError).message).toContain('"distanceCm"');
      expect((error as HalError).details).toMatchObject({
        call: 'moveForward',
        parameter: 'distanceCm',
      });
    });

    it('refuses an out-of-range finite value with RANGE_EXCEEDED quoting the limit from the config', () => {
      const limit = Math.floor(maxDistancePerCommandCm(V1_ROBOT) * 10) / 10;
      expect(() => boundary().validate('moveForward', { distanceCm: 500 })).toThrow(
        new RegExp(`"distanceCm" must be at most ${limit}, got 500`),
      );
      try {
        boundary().validate('drive', { left: -300, right: 0 });
      } catch (e) {
        expect((e as HalError).code).toBe('RANGE_EXCEEDED');
        expect((e as HalError).details).toMatchObject({
          parameter: 'left',
          limit: -255,
          bound: 'min',
        });
      }
      expect.assertions(3);
    });

    it('takes its limits from the robot configuration, not literals', () => {
      const slow = robotConfig({ maxStepsPerCommand: 2172 });
      expect(() =>
        boundary({ config: slow }).validate('moveForward', { distanceCm: 10.5 }),
      ).toThrow(/at most 9\.9/);
      expect(() => boundary().validate('moveForward', { distanceCm: 10.5 })).not.toThrow();
    });

    it('refuses an unknown enum value listing the allowed ones', () => {
      expect(() => boundary().validate('rotate', { direction: 'up', degrees: 90 })).toThrow(
        /"direction" must be one of "left", "right", got "up"/,
      );
    });

    it('refuses non-integer LED channels with INVALID_PARAMETER', () => {
      expect(() => boundary().validate('setLED', { r: 1.5, g: 0, b: 0 })).toThrow(HalError);
    });

    it("gives zod's output on its fast path: unknown keys dropped, an omitted argument kept as undefined", () => {
      const b = boundary();
      const led = { r: 1, g: 2, b: 3, pattern: undefined, brightness: 9 };
      expect(b.validate('setLED', led)).toStrictEqual(b.schemas().setLED.parse(led));
      expect(b.validate('setLED', led)).toStrictEqual({ r: 1, g: 2, b: 3, pattern: undefined });
      expect(b.validate('drive', { left: -255, right: 255 })).toStrictEqual({
        left: -255,
        right: 255,
      });
    });

    it('still takes what only zod models: an e-stop reason is sanitised, never refused', () => {
      expect(boundary().validate('emergencyStop', { reason: ' \u0007bumper\n' })).toStrictEqual({
        reason: 'bumper',
      });
      expect(boundary().validate('emergencyStop', { reason: { not: 'text' } })).toStrictEqual({
        reason: 'emergency stop',
      });
    });
  });

  describe('#call', () => {
    it('runs the body and returns a timed success stamped with the mode', async () => {
      const result = await boundary().call('moveForward', { distanceCm: 5 }, async (p) => ({
        moved: p.distanceCm,
      }));
      expect(HALToolResultSchema.parse(result)).toMatchObject({
        success: true,
        data: { moved: 5 },
        mode: 'simulation',
        executionTime: 5,
      });
    });

    it('does not run the body when validation fails', async () => {
      let ran = false;
      const result = await boundary().call('moveForward', { distanceCm: -1 }, async () => {
        ran = true;
      });
      expect(ran).toBe(false);
      expect(result).toMatchObject({ success: false, code: 'RANGE_EXCEEDED' });
    });

    it('refuses motion with EMERGENCY_STOPPED while latched, but not stop()', async () => {
      const b = boundary({ estop: true });
      expect(await b.call('drive', { left: 1, right: 1 }, async () => undefined)).toMatchObject({
        success: false,
        code: 'EMERGENCY_STOPPED',
      });
      expect((await b.call('stop', {}, async () => undefined)).success).toBe(true);
      expect((await b.call('setLED', { r: 1, g: 2, b: 3 }, async () => undefined)).success).toBe(
        true,
      );
    });

    it('refuses every call with NOT_READY before initialisation', async () => {
      const result = await boundary({ ready: false }).call('stop', {}, async () => undefined);
      expect(result).toMatchObject({ success: false, code: 'NOT_READY' });
    });

    it('converts a thrown HalError into its code and anything else into HARDWARE_ERROR', async () => {
      const b = boundary();
      const timeout = await b.call('stop', {}, async () => {
        throw new HalError('TIMEOUT', 'no reply', { details: { waitedMs: 2000 } });
      });
      expect(timeout).toMatchObject({
        success: false,
        code: 'TIMEOUT',
        error: 'no reply',
        details: { waitedMs: 2000 },
      });
      const crash = await b.call('stop', {}, async () => {
        throw new TypeError('boom');
      });
      expect(crash).toMatchObject({ success: false, code: 'HARDWARE_ERROR', error: 'boom' });
    });
  });

  describe('#schemas', () => {
    it('shares the call schemas of equal configurations between boundaries, and follows a change', () => {
      const first = boundary({ config: { ...V1_ROBOT } });
      const second = boundary({ config: { ...V1_ROBOT } });
      expect(second.schemas()).toBe(first.schemas());
      const state: { config: RobotConfig } = { config: { ...V1_ROBOT } };
      const changing = boundary(state);
      const before = changing.schemas();
      state.config = robotConfig({
        ...V1_ROBOT,
        maxStepsPerCommand: V1_ROBOT.maxStepsPerCommand / 2,
      });
      expect(changing.schemas()).not.toBe(before);
      const cm = maxDistancePerCommandCm(state.config);
      expect(() => changing.validate('moveForward', { distanceCm: cm * 1.5 })).toThrow(HalError);
      expect(() => first.validate('moveForward', { distanceCm: cm * 1.5 })).not.toThrow();
    });
  });
});
