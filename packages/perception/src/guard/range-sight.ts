import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { bounded } from './bounded.js';
import type { Sight, Sighting } from './sighting.js';

const DIAGONAL = Math.SQRT1_2;

/**
 * Looks ahead with the range sensors (`getDistanceSensors`, measured from the body's edge): the
 * front reading, and a diagonal's reading where what it sees lies inside the corridor.
 * NOT_IMPLEMENTED when the robot has none (or reports them `unavailable`).
 */
export class RangeSight implements Sight {
  readonly source = 'range' as const;
  readonly #hal: HardwareAbstractionLayer;
  readonly #bodyRadiusM: number;
  readonly #halfWidthM: number;
  readonly #timeoutMs: number;

  constructor(
    hal: HardwareAbstractionLayer,
    geometry: { bodyRadiusM: number; halfWidthM: number; timeoutMs: number },
  ) {
    this.#hal = hal;
    this.#bodyRadiusM = geometry.bodyRadiusM;
    this.#halfWidthM = geometry.halfWidthM;
    this.#timeoutMs = geometry.timeoutMs;
  }

  async look(): Promise<Sighting> {
    const reading = await bounded(
      this.#hal.vision.getDistanceSensors(),
      this.#timeoutMs,
      'range reading',
    );
    if (reading.source === 'unavailable') {
      throw new HalError('NOT_IMPLEMENTED', 'the robot reports no range sensors');
    }
    const maxM = reading.limits?.maxM ?? Number.POSITIVE_INFINITY;
    let aheadM = reading.front;
    for (const diagonal of [reading.frontLeft, reading.frontRight]) {
      if (diagonal === undefined || diagonal >= maxM) continue;
      // where the diagonal's reading lies, from the robot's centre
      const fromCentre = this.#bodyRadiusM + diagonal;
      if (fromCentre * DIAGONAL > this.#halfWidthM) continue;
      aheadM = Math.min(aheadM, Math.max(0, fromCentre * DIAGONAL - this.#bodyRadiusM));
    }
    const minM = reading.limits?.minM ?? 0;
    return {
      aheadM: Math.max(0, aheadM),
      blocked: aheadM < maxM - 1e-6,
      atEdge: reading.front <= minM,
      source: 'range',
      at: Date.now(),
    };
  }
}
