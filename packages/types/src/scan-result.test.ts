import { describe, expect, it } from 'vitest';
import { ScanResultSchema } from './pose.js';

describe('ScanResultSchema', () => {
  it('still takes a scan without the optional fields', () => {
    const plain = {
      objects: [
        { id: 'seen-1', type: 'obstacle', position: { x: 1, y: 0, z: 0 }, confidence: 0.5 },
      ],
      clearAhead: true,
    };
    expect(ScanResultSchema.parse(plain)).toEqual(plain);
  });

  it("keeps the frame and each object's bearing, distance, size and sensor", () => {
    const scan = {
      objects: [
        {
          id: 'seen-1',
          type: 'obstacle',
          position: { x: 0.9, y: 0, z: 0 },
          confidence: 0.875,
          bearingDeg: -1.5,
          distanceM: 0.83,
          sizeM: 0.2,
          sensor: 'range' as const,
        },
      ],
      clearAhead: true,
      nearestObstacle: 0.83,
      frame: 'odometry' as const,
      source: 'simulation' as const,
    };
    expect(ScanResultSchema.parse(scan)).toEqual(scan);
  });

  it('refuses an unknown frame or sensor, and a bearing that is not a number', () => {
    const object = { id: 'a', type: 'obstacle', position: { x: 0, y: 0, z: 0 }, confidence: 1 };
    const bad = [
      { objects: [], clearAhead: true, frame: 'map' },
      { objects: [{ ...object, sensor: 'lidar' }], clearAhead: true },
      { objects: [{ ...object, bearingDeg: Number.NaN }], clearAhead: true },
    ];
    for (const scan of bad) expect(ScanResultSchema.safeParse(scan).success).toBe(false);
  });
});
