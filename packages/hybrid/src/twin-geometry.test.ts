import { describe, expect, it } from 'vitest';
import { hybridRig } from './testing.fixture.js';

const CALIBRATED = { wheelDiameterCm: 6.6, wheelBaseCm: 10.4 };

describe('HybridHAL twin geometry', () => {
  it("gives the twin the physical robot's calibrated wheels, so both make the same steps", async () => {
    const { hal, robot, twin } = hybridRig({ physical: { calibration: () => CALIBRATED } });
    await hal.initialize();
    expect(twin.robotConfig).toMatchObject(CALIBRATED);
    const result = await hal.locomotion.moveForward(10);
    expect(result.success, JSON.stringify(result)).toBe(true);
    // 10 cm on 6.6 cm wheels; a twin on the nominal 6 cm wheels would make 2172
    expect(robot.position).toEqual({ left: 1975, right: 1975 });
    expect((await twin.locomotion.getPose()).position.x).toBeCloseTo(0.1, 3);
    expect(hal.getDivergence()?.positionM).toBeLessThan(0.001);
    const turned = await hal.locomotion.rotate('left', 90);
    expect(turned.success, JSON.stringify(turned)).toBe(true);
    expect(hal.getDivergence()?.yawRad).toBeLessThan(0.001);
    await hal.cleanup();
  });

  it("keeps the twin's own geometry with twinGeometry 'own'", async () => {
    const { hal, twin } = hybridRig({
      physical: { calibration: () => CALIBRATED },
      twin: { robot: { wheelDiameterCm: 5.5 } },
      hybrid: { twinGeometry: 'own' },
    });
    await hal.initialize();
    expect(twin.robotConfig.wheelDiameterCm).toBe(5.5);
    await hal.cleanup();
  });
});
