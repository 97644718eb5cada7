import { describe, expect, it } from 'vitest';
import { SimulationHAL } from '../hal/simulation-hal.js';
import type { BodyErrorInput } from './body-error.js';

/** Drives 30 cm straight ahead, then turns left 90°: where the body went, and what it reports. */
async function drive(bodyError?: BodyErrorInput) {
  const hal = new SimulationHAL(bodyError === undefined ? {} : { bodyError });
  await hal.initialize();
  const moved = await hal.locomotion.moveForward(30);
  const afterMove = {
    truth: { x: hal.robot.x, y: hal.robot.y },
    reported: (await hal.locomotion.getPose()).position,
    result: moved.data?.['pose'] as { x: number; y: number },
  };
  await hal.locomotion.rotate('left', 90);
  const pose = await hal.locomotion.getPose();
  const out = {
    afterMove,
    truthYaw: hal.robot.yaw,
    reportedYaw: pose.rotation.yaw,
  };
  await hal.cleanup();
  return out;
}

describe('SimRobot with a body error', () => {
  it('reports the true pose when no error is switched on', async () => {
    const { afterMove, truthYaw, reportedYaw } = await drive();
    expect(afterMove.reported.x).toBe(afterMove.truth.x);
    expect(afterMove.reported.y).toBe(afterMove.truth.y);
    expect(reportedYaw).toBe(truthYaw);
  });

  it('moves the body farther or shorter than its odometry says when the wheel diameters are off', async () => {
    const { afterMove, truthYaw, reportedYaw } = await drive({
      wheelDiameterErrorPct: 3,
      seed: 7,
    });
    // the odometry counts the nominal wheel: it says 30 cm, in the result and in getPose
    expect(afterMove.reported.x).toBeCloseTo(0.3, 4);
    expect(afterMove.result.x).toBeCloseTo(0.3, 4);
    const error = Math.hypot(afterMove.truth.x - 0.3, afterMove.truth.y);
    expect(error).toBeGreaterThan(0.0005);
    expect(error).toBeLessThan(0.3 * 0.09 * 1.5);
    expect(reportedYaw).toBeCloseTo(Math.PI / 2, 3);
    expect(Math.abs(truthYaw - Math.PI / 2)).toBeGreaterThan(0.001);
  });

  it('loses ground travel to wheel slip: the body always ends short of what the odometry says', async () => {
    for (const seed of [1, 2, 3]) {
      const { afterMove } = await drive({ wheelSlipPct: 10, seed });
      expect(afterMove.reported.x).toBeCloseTo(0.3, 4);
      const along = Math.hypot(afterMove.truth.x, afterMove.truth.y);
      expect(along).toBeLessThan(0.3 - 0.0001);
      expect(along).toBeGreaterThan(0.3 * 0.9 - 0.0001);
    }
  });

  it('lets the odometry drift from a body that moves as commanded when the odometry is noisy', async () => {
    const exact = await drive();
    const { afterMove, truthYaw, reportedYaw } = await drive({ odometryNoisePct: 3, seed: 5 });
    expect(afterMove.truth.x).toBe(exact.afterMove.truth.x);
    expect(truthYaw).toBe(exact.truthYaw);
    const drift = Math.hypot(
      afterMove.reported.x - afterMove.truth.x,
      afterMove.reported.y - afterMove.truth.y,
    );
    expect(drift).toBeGreaterThan(0.0005);
    expect(Math.abs(reportedYaw - truthYaw)).toBeGreaterThan(0.001);
  });

  it('grows the error with the knob, on average over seeds', async () => {
    const meanError = async (pct: number) => {
      let sum = 0;
      for (let seed = 1; seed <= 8; seed += 1) {
        const { afterMove } = await drive({ wheelDiameterErrorPct: pct, seed });
        sum += Math.hypot(afterMove.truth.x - afterMove.reported.x, afterMove.truth.y);
      }
      return sum / 8;
    };
    expect(await meanError(4)).toBeGreaterThan(await meanError(1));
  });

  it('draws the same errors from the same seed, and others from another', async () => {
    const knobs = { wheelDiameterErrorPct: 2, wheelSlipPct: 5, odometryNoisePct: 2 };
    const a = await drive({ ...knobs, seed: 11 });
    const b = await drive({ ...knobs, seed: 11 });
    const c = await drive({ ...knobs, seed: 12 });
    expect(b).toEqual(a);
    expect(c.afterMove.truth.x).not.toBe(a.afterMove.truth.x);
  });

  it('refuses a knob out of range with INVALID_PARAMETER naming it', () => {
    expect(() => new SimulationHAL({ bodyError: { wheelSlipPct: 80 } })).toThrow(
      expect.objectContaining({
        code: 'INVALID_PARAMETER',
        message: expect.stringMatching(/^"bodyError\.wheelSlipPct" /),
      }),
    );
  });
});
