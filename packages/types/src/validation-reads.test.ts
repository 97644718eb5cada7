import { describe, expect, it } from 'vitest';
import type { HalError } from './errors.js';
import { isHalError } from './errors.js';
import { HALToolResultSchema } from './result.js';
import {
  ConnectionConfigSchema,
  HALConfigSchema,
  minLinearSpeedMPerS,
  robotConfig,
  V1_ROBOT,
} from './robot-config.js';
import type { RobotConfig } from './robot-config.js';
import { HalBoundary } from './validation.js';

function boundary(state: { ready?: boolean; estop?: boolean; config?: RobotConfig } = {}) {
  return new HalBoundary({
    mode: 'physical',
    config: () => state.config ?? V1_ROBOT,
    isEmergencyStopped: () => state.estop ?? false,
    isReady: () => state.ready ?? true,
  });
}

async function rejection(promise: Promise<unknown>): Promise<HalError> {
  const error = await promise.then(
    () => undefined,
    (e: unknown) => e,
  );
  if (!isHalError(error)) throw new Error(`expected a HalError, got ${String(error)}`);
  return error;
}

describe('HalBoundary', () => {
  describe('#read', () => {
    it('rejects NOT_READY before running the body when the HAL is not ready', async () => {
      let ran = false;
      const error = await rejection(
        boundary({ ready: false }).read('getPose', {}, () => {
          ran = true;
        }),
      );
      expect(error.code).toBe('NOT_READY');
      expect(error.message).toMatch(/^getPose: /);
      expect(ran).toBe(false);
    });

    it('rejects an unknown scan mode with INVALID_PARAMETER listing the modes', async () => {
      const error = await rejection(boundary().read('scan', { mode: 'bogus' }, () => 'ran'));
      expect(error.code).toBe('INVALID_PARAMETER');
      expect(error.message).toContain('"mode" must be one of "full", "targeted", "quick"');
      expect(error.details).toMatchObject({ call: 'scan', parameter: 'mode', received: '"bogus"' });
    });

    it('passes the checked parameters to the body and answers its value, even while e-stopped', async () => {
      const value = await boundary({ estop: true }).read('scan', { mode: 'full' }, (p) => p.mode);
      expect(value).toBe('full');
      await expect(boundary().read('scan', {}, (p) => p.mode ?? 'default')).resolves.toBe(
        'default',
      );
    });

    it('turns anything else the body throws into a HARDWARE_ERROR that keeps the cause', async () => {
      const cause = new TypeError('socket closed');
      const error = await rejection(
        boundary().read('captureFrame', {}, async () => {
          throw cause;
        }),
      );
      expect(error.code).toBe('HARDWARE_ERROR');
      expect(error.cause).toBe(cause);
    });
  });

  describe('#notify', () => {
    it('runs the body with the checked parameters and returns a successful result', () => {
      const seen: unknown[] = [];
      const result = boundary().notify('log', { message: 'hi', level: 'warn' }, (p) => {
        seen.push(p);
      });
      expect(HALToolResultSchema.parse(result).success).toBe(true);
      expect(seen).toEqual([{ message: 'hi', level: 'warn' }]);
    });

    it.each([
      ['an unknown level', { message: 'x', level: 'bogus' }, 'INVALID_PARAMETER', '"level"'],
      ['a number', { message: 42 }, 'INVALID_PARAMETER', '"message"'],
      ['nothing', {}, 'INVALID_PARAMETER', '"message"'],
      ['a huge message', { message: 'x'.repeat(2001) }, 'INVALID_PARAMETER', '"message"'],
    ])('refuses %s without running the body and without throwing', (_t, args, code, name) => {
      let ran = false;
      const result = boundary().notify('log', args, () => {
        ran = true;
      });
      expect(result).toMatchObject({ success: false, code });
      expect(result.error).toContain(name);
      expect(ran).toBe(false);
    });

    it('returns a failed result, never a throw, when the body throws or the HAL is not ready', () => {
      const thrown = boundary().notify('log', { message: 'x' }, () => {
        throw new Error('logger broke');
      });
      expect(thrown).toMatchObject({ success: false, code: 'HARDWARE_ERROR' });
      const early = boundary({ ready: false }).notify('log', { message: 'x' }, () => undefined);
      expect(early).toMatchObject({ success: false, code: 'NOT_READY' });
    });
  });

  describe('moveTo speed', () => {
    it("refuses a speed below the robot's slowest with RANGE_EXCEEDED quoting the limit", () => {
      const slowest = Math.ceil(minLinearSpeedMPerS(V1_ROBOT) * 1e4) / 1e4;
      expect(slowest).toBe(0.003);
      for (const speed of [1e-9, 0, -1, 0.0029]) {
        const error = (() => {
          try {
            boundary().validate('moveTo', { x: 1, y: 0, z: 0, speed });
          } catch (e) {
            return e;
          }
          return undefined;
        })();
        expect(isHalError(error) && error.code, String(speed)).toBe('RANGE_EXCEEDED');
        expect((error as HalError).message).toContain(`"speed" must be at least ${slowest}`);
        expect((error as HalError).details).toMatchObject({ limit: slowest, bound: 'min' });
      }
      expect(boundary().validate('moveTo', { x: 1, y: 0, z: 0, speed: slowest })).toMatchObject({
        speed: slowest,
      });
    });

    it('takes the slowest speed from the robot configuration, never above its top speed', () => {
      const slow = robotConfig({ minSpeedStepsPerS: 512 });
      expect(() =>
        boundary({ config: slow }).validate('moveTo', { x: 1, y: 0, z: 0, speed: 0.01 }),
      ).toThrow(/"speed" must be at least 0\.0236/);
      const crawler = robotConfig({ maxSpeedStepsPerS: 32 });
      const top = Math.floor((32 / (4096 / (Math.PI * 6)) / 100) * 1e4) / 1e4;
      expect(
        boundary({ config: crawler }).validate('moveTo', { x: 1, y: 0, z: 0, speed: top }),
      ).toMatchObject({ speed: top });
    });
  });
});

describe('ConnectionConfigSchema', () => {
  it('refuses a link type without a transport, listing the supported ones', () => {
    const parsed = ConnectionConfigSchema.safeParse({ type: 'bluetooth' });
    expect(parsed.success).toBe(false);
    expect(parsed.error?.issues[0]?.message).toBe(
      'connection.type must be one of "serial", "wifi" (the links with a transport), got "bluetooth"',
    );
    expect(
      HALConfigSchema.safeParse({
        mode: 'physical',
        deviceId: 'cube-1',
        connection: { type: 'bluetooth' },
      }).success,
    ).toBe(false);
    expect(ConnectionConfigSchema.parse({ type: 'serial', port: '/dev/ttyUSB0' }).type).toBe(
      'serial',
    );
  });
});
