import { HalError } from '@hal/types';
import type { DistanceSensors, HardwareAbstractionLayer } from '@hal/types';
import { describe, expect, it } from 'vitest';
import { RangeSight } from './range-sight.js';

function halReading(reading: DistanceSensors | Error): HardwareAbstractionLayer {
  return {
    vision: {
      getDistanceSensors: () =>
        reading instanceof Error ? Promise.reject(reading) : Promise.resolve(reading),
    },
  } as unknown as HardwareAbstractionLayer;
}

const geometry = { bodyRadiusM: 0.07, halfWidthM: 0.09, timeoutMs: 1000 };
const limits = { minM: 0.02, maxM: 2, fieldOfViewDeg: 25 };

describe('RangeSight', () => {
  it('sees ahead the front reading, from the body edge', async () => {
    const sight = new RangeSight(
      halReading({ front: 0.4, left: 2, right: 2, frontLeft: 2, frontRight: 2, limits }),
      geometry,
    );
    await expect(sight.look()).resolves.toMatchObject({
      aheadM: 0.4,
      blocked: true,
      atEdge: false,
      source: 'range',
    });
  });

  it("takes a diagonal's reading where what it sees lies in the corridor", async () => {
    // 0.03 m on the diagonal: 0.1 m from the centre, 0.071 m to the side (inside 0.09)
    const near = new RangeSight(
      halReading({ front: 1, left: 2, right: 2, frontLeft: 0.03, frontRight: 2, limits }),
      geometry,
    );
    expect((await near.look()).aheadM).toBeCloseTo(0.1 * Math.SQRT1_2 - 0.07, 6);
    // 0.5 m on the diagonal is well to the side: not in the way
    const aside = new RangeSight(
      halReading({ front: 1, left: 2, right: 2, frontLeft: 2, frontRight: 0.5, limits }),
      geometry,
    );
    expect((await aside.look()).aheadM).toBe(1);
  });

  it('sees nothing in the way at the range limit, and at the edge at its shortest reading', async () => {
    const clear = new RangeSight(halReading({ front: 2, left: 2, right: 2, limits }), geometry);
    expect(await clear.look()).toMatchObject({ aheadM: 2, blocked: false });
    const touching = new RangeSight(
      halReading({ front: 0.02, left: 2, right: 2, limits }),
      geometry,
    );
    expect(await touching.look()).toMatchObject({ atEdge: true, blocked: true });
  });

  it('rejects NOT_IMPLEMENTED for sensors reported unavailable, and passes the HAL refusal on', async () => {
    const unavailable = new RangeSight(
      halReading({ front: 0, left: 0, right: 0, source: 'unavailable' }),
      geometry,
    );
    await expect(unavailable.look()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
    const none = new RangeSight(
      halReading(new HalError('NOT_IMPLEMENTED', 'no range sensors')),
      geometry,
    );
    await expect(none.look()).rejects.toMatchObject({ code: 'NOT_IMPLEMENTED' });
  });
});
