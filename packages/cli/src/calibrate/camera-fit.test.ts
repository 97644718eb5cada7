import { SimulationHAL, World } from '@hal/simulation';
import { cameraModel, V1_CAMERA } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';
import { fitCamera, tiltFor } from './camera-fit.js';
import { findTarget } from './camera-target.js';

const SIZE = 0.2;
const hals: SimulationHAL[] = [];
afterEach(async () => {
  for (const hal of hals.splice(0)) await hal.cleanup();
});

/** A simulator whose camera has `camera`'s settings, a red box's near face `nearM` straight ahead. */
async function redBoxAt(nearM: number, camera: { tiltDeg: number; heightM?: number }) {
  const world = new World({
    map: {
      name: 'target',
      obstacles: [
        {
          kind: 'box',
          x: nearM + SIZE / 2,
          y: 0,
          width: SIZE,
          depth: SIZE,
          height: SIZE,
          color: '#d62828',
        },
      ],
    },
  });
  const hal = new SimulationHAL({ world, camera });
  hals.push(hal);
  await hal.initialize();
  return hal;
}

describe('fitCamera', () => {
  it.each([0.3, 0.5, 0.8])(
    'gets a 15-degree tilt back within 0.5 degrees from a red box at %s m, assuming V1 20',
    async (nearM) => {
      const hal = await redBoxAt(nearM, { tiltDeg: 15 });
      const seen = await findTarget(hal, V1_CAMERA, 'red', { frames: 3 });
      const fit = fitCamera(V1_CAMERA, [{ distanceM: nearM, ...seen }]);
      expect(Math.abs(fit.model.tiltDeg - 15)).toBeLessThan(0.5);
      expect(fit.fittedHeight).toBe(false);
      expect(fit.model.heightM).toBe(V1_CAMERA.heightM);
      expect(fit.residualM).toBeLessThan(1e-6);
    },
  );

  it('fits the lens height too from two distances: 12 cm and 25 degrees back', async () => {
    const camera = { tiltDeg: 25, heightM: 0.12 };
    const sightings = [];
    for (const nearM of [0.35, 0.8]) {
      const hal = await redBoxAt(nearM, camera);
      sightings.push({ distanceM: nearM, ...(await findTarget(hal, V1_CAMERA, 'red')) });
    }
    const fit = fitCamera(V1_CAMERA, sightings);
    expect(fit.fittedHeight).toBe(true);
    expect(Math.abs(fit.model.tiltDeg - 25)).toBeLessThan(1);
    expect(Math.abs(fit.model.heightM - 0.12)).toBeLessThan(0.01);
    expect(fit.residualM).toBeLessThan(0.01);
  });

  it('refuses a distance no tilt in the schema range can explain, naming the range', () => {
    // the middle row 1 cm ahead of a lens 9 cm up would need a tilt of 84 degrees
    const nearly = { distanceM: 0.06, row: 120, column: 160 };
    expect(tiltFor(V1_CAMERA, nearly)).toBeUndefined();
    expect(() => fitCamera(V1_CAMERA, [nearly])).toThrow(
      /no camera tilt in -45\.\.80 degrees puts the target's base at 6\.0 cm/,
    );
  });

  it('is exact on the model it projects with, off the middle column too', () => {
    const model = cameraModel({ tiltDeg: 31.25 });
    const tilt = tiltFor(V1_CAMERA, { distanceM: 0.4, row: 150, column: 60 });
    const back = tiltFor(model, { distanceM: 0.4, row: 150, column: 60 });
    expect(back).toBeCloseTo(tilt!, 9);
  });
});

describe('findTarget', () => {
  it('says when the target is not in view', async () => {
    const hal = await redBoxAt(0.5, { tiltDeg: 15 });
    await expect(findTarget(hal, V1_CAMERA, 'blue', { frames: 2 })).rejects.toMatchObject({
      code: 'NOT_FOUND',
      message: expect.stringContaining('no blue target in 2 frames'),
    });
  });

  it('refuses a target cut by the bottom of the image: its base is out of view', async () => {
    const hal = await redBoxAt(0.08, { tiltDeg: 15 });
    await expect(findTarget(hal, V1_CAMERA, 'red', { frames: 2 })).rejects.toMatchObject({
      code: 'FAILED',
      message: expect.stringContaining('cut by the bottom of the image'),
    });
  });
});
