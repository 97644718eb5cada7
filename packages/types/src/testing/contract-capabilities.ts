import { describe, expect, it } from 'vitest';
import { CAPABILITIES, hasCapability } from '../capabilities.js';
import { IMUReadingSchema, ScanResultSchema } from '../pose.js';
import { FrameDataUrlSchema, LineSensorsSchema } from '../schemas/reads.js';
import type { ContractContext } from './contract-expect.js';
import { expectFailedResult, expectRejected, expectSucceeded, settle } from './contract-expect.js';

/**
 * Capabilities are honest for the camera, the LED, the IMU, line sensors and scanning: offered,
 * the call works and answers well-formed; not offered, it fails NOT_IMPLEMENTED (or, for a
 * reading, answers a value derived from what the robot has, marked with its source).
 */
export function describeCapabilityContract(ctx: ContractContext): void {
  const { timeout } = ctx;

  describe('capabilities are honest (camera, LED, IMU, line sensors, scan)', () => {
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
