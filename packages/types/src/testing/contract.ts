import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { CAPABILITIES, hasCapability, parseCapability } from '../capabilities.js';
import { isHalError } from '../errors.js';
import { describeEstopContract } from './contract-estop.js';
import type { HalErrorCode } from '../errors.js';
import type { HardwareAbstractionLayer } from '../interfaces.js';
import { DeviceInfoSchema, PoseSchema, SafetyStatusSchema } from '../pose.js';
import type { Pose } from '../pose.js';
import { HALToolResultSchema } from '../result.js';
import { angleDifference } from '../vocabulary/angle.js';
import type { HALToolResult } from '../result.js';
import { invokeSpec } from '../schemas/invoke-call.js';
import { describeBoundaryContract } from './contract-boundary.js';
import { describeCapabilityContract } from './contract-capabilities.js';
import { describeCoverageContract } from './contract-coverage.js';
import { describeLifecycleContract } from './contract-lifecycle.js';
import { describeResultContract } from './contract-results.js';
import { sampledCalls } from './contract-samples.js';

/** How the contract suite gets, and gets rid of, the HAL under test. */
export interface HalContractOptions {
  /** Makes a fresh HAL that has not been initialised, at the origin, facing +x. */
  create: () => HardwareAbstractionLayer | Promise<HardwareAbstractionLayer>;
  /** Releases what `create` made (a server, an emulator), after the HAL's own cleanup. */
  dispose?: (hal: HardwareAbstractionLayer) => void | Promise<void>;
  /** Position tolerance, metres. Default 0.002 (2 mm). */
  positionTolerance?: number;
  /** Yaw tolerance, radians. Default 0.01. */
  yawTolerance?: number;
  /** Timeout of each test, ms (motions on a real robot take seconds). Default 30000. */
  timeoutMs?: number;
}

function expectFailure(result: HALToolResult, code: HalErrorCode): void {
  expect(HALToolResultSchema.safeParse(result).success, JSON.stringify(result)).toBe(true);
  expect(result.success, JSON.stringify(result)).toBe(false);
  expect(result.code, JSON.stringify(result)).toBe(code);
  expect(result.error).toEqual(expect.any(String));
}

function expectSuccess(result: HALToolResult): void {
  expect(HALToolResultSchema.safeParse(result).success, JSON.stringify(result)).toBe(true);
  expect(result.success, JSON.stringify(result)).toBe(true);
}

/**
 * The behaviour every {@link HardwareAbstractionLayer} must show, as a vitest suite: lifecycle,
 * result shape, validation, e-stop gating, honest capabilities, and the pose after known motions
 * (which also pins the REP-103 direction of every call). Call it inside a test file.
 */
export function describeHalContract(name: string, options: HalContractOptions): void {
  const posTol = options.positionTolerance ?? 0.002;
  const yawTol = options.yawTolerance ?? 0.01;
  const timeout = options.timeoutMs ?? 30_000;

  describe(`${name} (HAL contract)`, () => {
    let hal: HardwareAbstractionLayer;

    beforeEach(async () => {
      hal = await options.create();
    }, timeout);

    afterEach(async () => {
      await hal.cleanup();
      await options.dispose?.(hal);
    }, timeout);

    const ready = async (): Promise<HardwareAbstractionLayer> => {
      await hal.initialize();
      return hal;
    };
    const pose = async (): Promise<Pose> => PoseSchema.parse(await hal.locomotion.getPose());

    describe('lifecycle', () => {
      it(
        'is not ready before initialize() and refuses motion with NOT_READY',
        { timeout },
        async () => {
          expect(hal.isReady()).toBe(false);
          expectFailure(await hal.locomotion.moveForward(1), 'NOT_READY');
        },
      );

      it('is ready after initialize() and describes itself', { timeout }, async () => {
        await ready();
        expect(hal.isReady()).toBe(true);
        const info = DeviceInfoSchema.parse(hal.getDeviceInfo());
        expect(info.mode).toBe(hal.mode);
        for (const capability of info.capabilities)
          expect(() => parseCapability(capability)).not.toThrow();
        expect(hasCapability(info.capabilities, CAPABILITIES.differentialDrive)).toBe(true);
      });

      it(
        'is not ready after cleanup(), and cleanup() may be called twice',
        { timeout },
        async () => {
          await ready();
          await hal.cleanup();
          expect(hal.isReady()).toBe(false);
          await hal.cleanup();
          expectFailure(await hal.locomotion.moveForward(1), 'NOT_READY');
        },
      );
    });

    describe('results', () => {
      it('stamps every result with its mode, time and duration', { timeout }, async () => {
        await ready();
        const result = await hal.locomotion.stop();
        expectSuccess(result);
        expect(result.mode).toBe(hal.mode);
        expect(result.executionTime).toBeGreaterThanOrEqual(0);
        expect(Number.isFinite(result.timestamp)).toBe(true);
      });

      it('starts at the origin facing +x, at rest', { timeout }, async () => {
        await ready();
        const start = await pose();
        expect(Math.hypot(start.position.x, start.position.y)).toBeLessThan(posTol);
        expect(Math.abs(start.rotation.yaw)).toBeLessThan(yawTol);
        expect(start.velocity.linear).toBe(0);
      });
    });

    describe('validation', () => {
      const bad: Array<
        [string, (h: HardwareAbstractionLayer) => Promise<HALToolResult>, HalErrorCode, string]
      > = [
        [
          'drive with NaN power',
          (h) => h.locomotion.drive(Number.NaN, 0),
          'INVALID_PARAMETER',
          'left',
        ],
        ['drive beyond full power', (h) => h.locomotion.drive(0, 300), 'RANGE_EXCEEDED', 'right'],
        [
          'drive with a negative duration',
          (h) => h.locomotion.drive(100, 100, -5),
          'RANGE_EXCEEDED',
          'durationMs',
        ],
        [
          'moveForward an infinite distance',
          (h) => h.locomotion.moveForward(Number.POSITIVE_INFINITY),
          'INVALID_PARAMETER',
          'distanceCm',
        ],
        [
          'moveForward a negative distance',
          (h) => h.locomotion.moveForward(-5),
          'RANGE_EXCEEDED',
          'distanceCm',
        ],
        [
          'moveForward further than one command allows',
          (h) => h.locomotion.moveForward(1e6),
          'RANGE_EXCEEDED',
          'distanceCm',
        ],
        [
          'moveBackward a string',
          (h) => h.locomotion.moveBackward('10' as unknown as number),
          'INVALID_PARAMETER',
          'distanceCm',
        ],
        [
          'rotate an unknown way',
          (h) => h.locomotion.rotate('up' as unknown as 'left', 90),
          'INVALID_PARAMETER',
          'direction',
        ],
        [
          'rotate NaN degrees',
          (h) => h.locomotion.rotate('left', Number.NaN),
          'INVALID_PARAMETER',
          'degrees',
        ],
        [
          'moveTo a NaN point',
          (h) => h.locomotion.moveTo(Number.NaN, 0, 0),
          'INVALID_PARAMETER',
          'x',
        ],
        ['moveTo too fast', (h) => h.locomotion.moveTo(0.1, 0, 0, 100), 'RANGE_EXCEEDED', 'speed'],
        ['setLED beyond 255', (h) => h.communication.setLED(300, 0, 0), 'RANGE_EXCEEDED', 'r'],
      ];
      for (const [title, call, code, parameter] of bad) {
        it(
          `refuses to ${title} with ${code}, naming "${parameter}", and nothing moves`,
          { timeout },
          async () => {
            await ready();
            const before = await pose();
            const result = await call(hal);
            expectFailure(result, code);
            expect(result.error).toContain(`"${parameter}"`);
            const after = await pose();
            expect(after.position).toEqual(before.position);
            expect(after.rotation.yaw).toBe(before.rotation.yaw);
          },
        );
      }
    });

    describe('emergency stop', () => {
      it(
        'latches, refuses every motion at once with EMERGENCY_STOPPED, and clears only on reset',
        { timeout },
        async () => {
          await ready();
          expect(hal.safety.isEmergencyStopped()).toBe(false);
          expectSuccess(await hal.safety.emergencyStop('contract test'));
          expect(hal.safety.isEmergencyStopped()).toBe(true);
          expect(SafetyStatusSchema.parse(hal.safety.getSafetyStatus()).emergencyStopped).toBe(
            true,
          );
          for (const [spec, args] of sampledCalls((entry) => entry.kind === 'motion')) {
            const refused = (await invokeSpec(hal, spec, args)) as HALToolResult;
            expect(refused.code, spec.name).toBe('EMERGENCY_STOPPED');
            expectFailure(refused, 'EMERGENCY_STOPPED');
          }
          expectSuccess(await hal.locomotion.stop());
          expect(hal.safety.isEmergencyStopped()).toBe(true);
          expect((await pose()).position.x).toBe(0);

          expectSuccess(await hal.safety.resetEmergencyStop());
          expect(hal.safety.isEmergencyStopped()).toBe(false);
          expectSuccess(await hal.locomotion.moveForward(1));
          expect((await pose()).position.x).toBeCloseTo(0.01, 3);
        },
      );
    });

    describeEstopContract(() => hal, timeout);

    describe('motion (REP-103: x forward, y left, yaw counter-clockwise)', () => {
      it('moveForward(10) ends 0.1 m ahead and moveBackward(10) returns', { timeout }, async () => {
        await ready();
        const forward = await hal.locomotion.moveForward(10);
        expectSuccess(forward);
        expect(forward.mode).toBe(hal.mode);
        let now = await pose();
        expect(Math.abs(now.position.x - 0.1)).toBeLessThan(posTol);
        expect(Math.abs(now.position.y)).toBeLessThan(posTol);
        expect(now.velocity.linear).toBe(0);
        expectSuccess(await hal.locomotion.moveBackward(10));
        now = await pose();
        expect(Math.abs(now.position.x)).toBeLessThan(posTol);
      });

      it(
        'rotate("left", 90) turns counter-clockwise to +pi/2, then forward goes +y',
        { timeout },
        async () => {
          await ready();
          expectSuccess(await hal.locomotion.rotate('left', 90));
          let now = await pose();
          expect(Math.abs(angleDifference(now.rotation.yaw, Math.PI / 2))).toBeLessThan(yawTol);
          expect(Math.hypot(now.position.x, now.position.y)).toBeLessThan(posTol);
          expectSuccess(await hal.locomotion.moveForward(5));
          now = await pose();
          expect(Math.abs(now.position.y - 0.05)).toBeLessThan(posTol);
          expect(Math.abs(now.position.x)).toBeLessThan(posTol);
        },
      );

      it('rotate("right", 90) turns clockwise to -pi/2', { timeout }, async () => {
        await ready();
        expectSuccess(await hal.locomotion.rotate('right', 90));
        const now = await pose();
        expect(Math.abs(angleDifference(now.rotation.yaw, -Math.PI / 2))).toBeLessThan(yawTol);
      });

      it('moveTo(x, y, 0) arrives at the point', { timeout }, async () => {
        await ready();
        const result = await hal.locomotion.moveTo(0.05, 0.05, 0);
        expectSuccess(result);
        const now = await pose();
        expect(Math.abs(now.position.x - 0.05)).toBeLessThan(posTol);
        expect(Math.abs(now.position.y - 0.05)).toBeLessThan(posTol);
      });

      it(
        'drive(-255, 255, ms) turns counter-clockwise and stops by itself',
        { timeout },
        async () => {
          await ready();
          expectSuccess(await hal.locomotion.drive(-255, 255, 400));
          const now = await pose();
          expect(now.rotation.yaw).toBeGreaterThan(0);
          expect(now.velocity.angular).toBe(0);
        },
      );
    });

    describe('capabilities are honest', () => {
      it('fails the calls of capabilities it lacks with NOT_IMPLEMENTED', { timeout }, async () => {
        await ready();
        const caps = hal.getDeviceInfo().capabilities;
        if (!hasCapability(caps, CAPABILITIES.speaker)) {
          expectFailure(await hal.communication.speak('hello'), 'NOT_IMPLEMENTED');
        } else {
          expectSuccess(await hal.communication.speak('hello'));
        }
        if (!hasCapability(caps, CAPABILITIES.sound)) {
          expectFailure(await hal.communication.playSound('beep'), 'NOT_IMPLEMENTED');
        }
        if (!hasCapability(caps, CAPABILITIES.rangeSensors)) {
          const reading = await hal.vision.getDistanceSensors().then(
            (value) => ({ value }),
            (error: unknown) => ({ error }),
          );
          if ('error' in reading) {
            expect(isHalError(reading.error) && reading.error.code).toBe('NOT_IMPLEMENTED');
          } else {
            expect(reading.value.source).not.toBe('sensor');
          }
        }
        if (hal.manipulation === undefined) {
          expect(caps.some((c) => c.startsWith('manipulation.'))).toBe(false);
        }
      });
    });

    const groups = { hal: () => hal, ready, timeout };
    describeBoundaryContract(groups);
    describeLifecycleContract(groups);
    describeCapabilityContract(groups);
    describeResultContract(groups);
    describeCoverageContract();
  });
}
