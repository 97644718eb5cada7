import { cameraModel, V1_CAMERA } from '@hal/types';
import { describe, expect, it } from 'vitest';
import {
  cameraProjection,
  floorPointOfPixel,
  focalLengthPx,
  horizonRow,
  nearestVisibleFloorM,
  pixelOfPoint,
  pixelRay,
} from './camera.js';

const v1 = cameraProjection(V1_CAMERA);

describe('the camera projection', () => {
  it("gives the V1 camera's focal length, horizon and nearest visible floor", () => {
    expect(focalLengthPx(V1_CAMERA)).toBeCloseTo(160 / Math.tan((31 * Math.PI) / 180), 9);
    // 20 degrees down: the horizon is f tan 20 above the centre row.
    expect(horizonRow(v1)).toBeCloseTo(120 - v1.f * Math.tan((20 * Math.PI) / 180), 9);
    // The bottom edge looks 20 + atan(120 / f) degrees down from 9 cm up, 5 cm ahead.
    const down = (20 * Math.PI) / 180 + Math.atan(120 / v1.f);
    expect(nearestVisibleFloorM(v1)).toBeCloseTo(0.05 + 0.09 / Math.tan(down), 9);
  });

  it('maps a floor point to its pixel and back, across the image', () => {
    for (const [u, v] of [
      [0.5, 239.5],
      [160, 120],
      [300.25, 40.75],
      [12, 30],
    ] as const) {
      const point = floorPointOfPixel(v1, u, v);
      expect(point).toBeDefined();
      const back = pixelOfPoint(v1, { x: point?.x ?? 0, y: point?.y ?? 0, z: 0 });
      expect(back?.u).toBeCloseTo(u, 9);
      expect(back?.v).toBeCloseTo(v, 9);
    }
  });

  it('puts the left of the image to the left of the robot (REP-103: +y)', () => {
    const left = floorPointOfPixel(v1, 10, 200);
    const right = floorPointOfPixel(v1, 310, 200);
    expect(left?.y).toBeGreaterThan(0);
    expect(right?.y).toBeLessThan(0);
    expect(pixelRay(v1, 160, 120)).toEqual({
      x: Math.cos((20 * Math.PI) / 180),
      y: -0,
      z: -Math.sin((20 * Math.PI) / 180),
    });
  });

  it('finds no floor at or above the horizon, and no pixel behind the lens', () => {
    expect(floorPointOfPixel(v1, 160, horizonRow(v1))).toBeUndefined();
    expect(floorPointOfPixel(v1, 160, 0)).toBeUndefined();
    expect(pixelOfPoint(v1, { x: -1, y: 0, z: 0 })).toBeUndefined();
  });

  it('holds for a level camera offset to the side', () => {
    const p = cameraProjection(cameraModel({ tiltDeg: 0, leftM: 0.02, width: 640, height: 480 }));
    expect(horizonRow(p)).toBe(240);
    const point = floorPointOfPixel(p, 320, 480);
    expect(point?.y).toBeCloseTo(0.02, 12);
    expect(point?.x).toBeCloseTo(0.05 + (0.09 * p.f) / 240, 12);
  });

  it('refuses an invalid model', () => {
    expect(() => cameraModel({ fieldOfViewDeg: Number.NaN })).toThrow();
    expect(() => cameraModel({ width: 0 })).toThrow();
    expect(() => cameraModel({ tiltDeg: 90 })).toThrow();
  });
});
