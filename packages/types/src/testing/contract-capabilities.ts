import { describe, expect, it } from 'vitest';
import { CAPABILITIES, hasCapability } from '../capabilities.js';
import { IMUReadingSchema, ScanResultSchema } from '../pose.js';
import { FrameDataUrlSchema, LineSensorsSchema } from '../schemas/reads.js';
import { isHalError } from '../errors.js';
import type { HALToolResult } from '../result.js';
import type { CallSpec } from '../schemas/call-table.js';
import { invokeSpec } from '../schemas/invoke-call.js';
import type { ContractContext } from './contract-expect.js';
import { expectFailedResult, expectRejected, expectSucceeded, settle } from './contract-expect.js';
import { sampledCalls } from './contract-samples.js';

/**
 * How the capability group exercises `spec`: every call that needs a capability other than the
 * wheels is made with and without it (every HAL offers the wheels: the lifecycle group checks it).
 */
export function capabilityCoverage(spec: CallSpec): string {
  const requires = spec.tool.requires;
  if (requires === undefined) return 'needs no capability';
  if (requires === CAPABILITIES.differentialDrive) return 'needs the wheels every HAL offers';
  return `made with and without ${requires}`;
}

/** Whether `value` is a reading marked as derived from something other than its own sensor. */
function derivedReading(value: unknown): boolean {
  if (value === null || typeof value !== 'object') return false;
  const source = (value as { source?: unknown }).source;
  return typeof source === 'string' && source !== 'sensor';
}

/**
 * Capabilities are honest for the camera, the LED, the IMU, line sensors and scanning: offered,
 * the call works and answers well-formed; not offered, it fails NOT_IMPLEMENTED (or, for a
 * reading, answers a value derived from what the robot has, marked with its source).
 */
export function describeCapabilityContract(ctx: ContractContext): void {
  const { timeout } = ctx;

  describe('capabilities are honest (camera, LED, IMU, line sensors, scan)', () => {
    it(
      'answers every call that needs a capability it lacks NOT_IMPLEMENTED (or a reading marked derived), and never NOT_IMPLEMENTED one it offers',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const offered = hal.getDeviceInfo().capabilities;
        const needs = (spec: CallSpec) =>
          spec.tool.requires !== undefined && spec.tool.requires !== CAPABILITIES.differentialDrive;
        for (const [spec, args] of sampledCalls(needs)) {
          const has = hasCapability(offered, spec.tool.requires ?? '');
          const label = `${spec.name} ${has ? 'with' : 'without'} ${spec.tool.requires ?? ''}:`;
          const outcome = await settle(() => invokeSpec(hal, spec, args));
          if (spec.kind === 'value') {
            if ('error' in outcome) {
              if (has)
                expect(isHalError(outcome.error) && outcome.error.code, label).not.toBe(
                  'NOT_IMPLEMENTED',
                );
              else expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, label);
            } else if (!has) {
              expect(
                derivedReading(outcome.value),
                `${label} ${JSON.stringify(outcome.value)}`,
              ).toBe(true);
            }
            continue;
          }
          expect('value' in outcome, `${label} rejected`).toBe(true);
          if (!('value' in outcome)) continue;
          const result = outcome.value as HALToolResult;
          if (has) expect(result.code, label).not.toBe('NOT_IMPLEMENTED');
          else expectFailedResult(result, 'NOT_IMPLEMENTED', undefined, label);
        }
      },
    );

    it(
      'captures a JPEG frame only when it offers the camera, else rejects NOT_IMPLEMENTED',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const outcome = await settle(() => hal.vision.captureFrame());
        if (hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.camera)) {
          expect('value' in outcome, JSON.stringify(outcome)).toBe(true);
          if ('value' in outcome)
            expect(FrameDataUrlSchema.safeParse(outcome.value).success).toBe(true);
        } else {
          expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, 'captureFrame:');
        }
      },
    );

    it(
      'sets the LED only when it offers the LED, else fails NOT_IMPLEMENTED',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const result = await hal.communication.setLED(0, 128, 255, 'blink');
        if (hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.led)) {
          expectSucceeded(result, 'setLED:');
        } else {
          expectFailedResult(result, 'NOT_IMPLEMENTED', undefined, 'setLED:');
        }
      },
    );

    it(
      'reads the IMU from a sensor only when it offers one, else from what it has',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const outcome = await settle(() => hal.vision.getIMU());
        const offered = hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.imu);
        if ('value' in outcome) {
          const reading = IMUReadingSchema.parse(outcome.value);
          if (!offered) expect(reading.source).not.toBe('sensor');
        } else {
          expect(offered, 'an offered IMU must answer').toBe(false);
          expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, 'getIMU:');
        }
      },
    );

    it(
      'reads line sensors only when it offers them, else rejects NOT_IMPLEMENTED',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const outcome = await settle(() => hal.vision.getLineSensors());
        if (hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.lineSensors)) {
          expect('value' in outcome && LineSensorsSchema.safeParse(outcome.value).success).toBe(
            true,
          );
        } else {
          expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, 'getLineSensors:');
        }
      },
    );

    it(
      'scans with range sensors only when it offers them, else marks or refuses the scan',
      { timeout },
      async () => {
        const hal = await ctx.ready();
        const outcome = await settle(() => hal.vision.scan('quick'));
        const offered = hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.rangeSensors);
        if ('value' in outcome) {
          const scan = ScanResultSchema.parse(outcome.value);
          if (!offered) expect(scan.source).not.toBe('sensor');
        } else {
          expect(offered, 'offered range sensors must scan').toBe(false);
          expectRejected(outcome, 'NOT_IMPLEMENTED', undefined, 'scan:');
        }
      },
    );
  });
}
