// scan from what a robot can know: on a robot with no range sensors (the V1 cube) the camera
// answers it through perception; where both exist, each object says which sensor saw it. All in
// the frame of the robot's reported pose.
import { Perception, withCameraScan } from '@hal/perception';
import { SimulationHAL, World } from '@hal/simulation';
import { isHalError } from '@hal/types';
import { afterEach, describe, expect, it } from 'vitest';

let hal: SimulationHAL | undefined;
afterEach(async () => {
  await hal?.cleanup();
  hal = undefined;
});

const world = () =>
  new World({
    map: {
      name: 'pillar and wall',
      walls: [{ from: [1.6, -2], to: [1.6, 2], thickness: 0.05 }],
      obstacles: [
        { kind: 'cylinder', x: 0.9, y: -0.2, radius: 0.15, height: 0.3, color: '#2a9d3f' },
      ],
    },
  });

describe('scan with the camera', () => {
  it('answers on a robot without range sensors, with what the camera sees, where it sees it', async () => {
    hal = new SimulationHAL({ world: world(), features: { rangeSensors: false } });
    await hal.initialize();
    const bare = await hal.vision.scan().catch((error: unknown) => error);
    expect(isHalError(bare) && bare.code).toBe('NOT_IMPLEMENTED');

    const seeing = withCameraScan(hal, new Perception(hal));
    const scan = await seeing.vision.scan();
    expect(scan.frame).toBe('odometry');
    expect(scan.objects.map((o) => [o.id, o.type, o.sensor])).toEqual([
      ['green pillar 1', 'pillar', 'camera'],
    ]);
    const [pillar] = scan.objects;
    expect(
      Math.hypot((pillar?.position.x ?? 0) - 0.9, (pillar?.position.y ?? 0) + 0.2),
    ).toBeLessThan(0.08);
    expect(pillar?.bearingDeg).toBeLessThan(0);
    // Everything else is the HAL's own.
    expect(seeing.mode).toBe('simulation');
    expect((await seeing.locomotion.getPose()).position.x).toBe(0);
  });

  it('keeps the range sensors where the robot has them, each object marked by its sensor', async () => {
    hal = new SimulationHAL({ world: world() });
    await hal.initialize();
    const scan = await withCameraScan(hal, new Perception(hal)).vision.scan('full');
    const sensors = new Set(scan.objects.map((o) => o.sensor));
    expect(sensors).toEqual(new Set(['range', 'camera']));
    expect(scan.nearestObstacle).toBeLessThan(1);
  });
});
