// The twin against the emulated robot: it follows a scripted sequence within 1 mm, and a twin
// built with the wrong wheels is reported as diverged.
import type { DivergenceEvent } from '@hal/hybrid';
import { afterAll, describe, expect, it } from 'vitest';
import { stopAllEmulators } from '../physical/emulator.js';
import { emulatedRig } from './rig.js';

afterAll(stopAllEmulators);

describe('HybridHAL against the emulator', () => {
  it('keeps the twin within 1 mm and 0.001 rad of the robot over a scripted sequence', async () => {
    const { hal, emulator } = await emulatedRig({
      hybrid: { divergence: { positionToleranceM: 0.001, yawToleranceRad: 0.001 } },
    });
    const events: DivergenceEvent[] = [];
    hal.onDivergence((event) => events.push(event));
    try {
      await hal.initialize();
      const script = [
        () => hal.locomotion.moveForward(12),
        () => hal.locomotion.rotate('left', 90),
        () => hal.locomotion.moveForward(5),
        () => hal.locomotion.rotate('right', 45),
        () => hal.locomotion.moveBackward(4),
        () => hal.locomotion.moveTo(0.05, -0.05, 0),
        () => hal.locomotion.drive(200, -120, 600),
        () => hal.communication.setLED(0, 0, 255),
        () => hal.locomotion.moveTo(0, 0, 0),
      ];
      let worst = 0;
      for (const step of script) {
        const result = await step();
        expect(result.success, JSON.stringify(result)).toBe(true);
        expect(result.mode).toBe('hybrid');
        expect(result.data).toMatchObject({
          twin: { success: true },
          divergence: { exceeded: false },
        });
        worst = Math.max(worst, hal.getDivergence()?.positionM ?? Number.POSITIVE_INFINITY);
      }
      expect(worst).toBeLessThan(0.001);
      expect(events).toEqual([]);
      const home = await hal.locomotion.getPose();
      expect(Math.hypot(home.position.x, home.position.y)).toBeLessThan(0.002);
    } finally {
      await hal.cleanup();
      await emulator.stop();
    }
  });

  it("reports a twin whose wheels are 10 % larger than the robot's as exceeded", async () => {
    // the twin keeps its own (wrong) wheels instead of taking the robot's
    const { hal, emulator } = await emulatedRig({
      twin: { robot: { wheelDiameterCm: 6.6 } },
      hybrid: { twinGeometry: 'own' },
    });
    const events: DivergenceEvent[] = [];
    hal.onDivergence((event) => events.push(event));
    try {
      await hal.initialize();
      const result = await hal.locomotion.drive(255, 255, 5000);
      expect(result.success, JSON.stringify(result)).toBe(true);
      expect(result.data).toMatchObject({
        twin: { success: true },
        divergence: { exceeded: true },
      });
      expect(events).toHaveLength(1);
      const [event] = events;
      // the same steps roll 10 % further on the twin's wheels
      expect(event?.twin.x).toBeCloseTo((event?.physical.x ?? 0) * 1.1, 4);
      expect(event?.divergence.positionM).toBeGreaterThan(0.005);
    } finally {
      await hal.cleanup();
      await emulator.stop();
    }
  });
});
