// One HAL script, two worlds: PhysicalHAL driving the emulated robot (the firmware core, over UDP)
// and SimulationHAL. After every call both succeed with the same commands, the same steps (to one
// step: see below) and the same pose to a millimetre, and the wheels end where each other's do.
// The exact, step-for-step agreement of the motion model itself is emulator-agreement.test.ts.
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL, World } from '@hal/simulation';
import type { HALToolResult, HardwareAbstractionLayer } from '@hal/types';
import { afterAll, describe, expect, it } from 'vitest';
import { LONGEST_HOST_TIMEOUT_MS, startEmulator, stopAllEmulators } from '../physical/emulator.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 20;

const SCRIPT: Array<[string, (hal: HardwareAbstractionLayer) => Promise<HALToolResult>]> = [
  ['moveForward(10)', (h) => h.locomotion.moveForward(10)],
  ['rotate(left, 90)', (h) => h.locomotion.rotate('left', 90)],
  ['moveForward(12.34)', (h) => h.locomotion.moveForward(12.34)],
  ['rotate(right, 45)', (h) => h.locomotion.rotate('right', 45)],
  ['moveTo(0.05, 0.25, 0)', (h) => h.locomotion.moveTo(0.05, 0.25, 0)],
  ['moveTo(-0.1, 0.1, 0, 0.02)', (h) => h.locomotion.moveTo(-0.1, 0.1, 0, 0.02)],
  ['drive(200, 150, 1500)', (h) => h.locomotion.drive(200, 150, 1500)],
  ['moveBackward(7.77)', (h) => h.locomotion.moveBackward(7.77)],
  ['rotate(left, 200.5)', (h) => h.locomotion.rotate('left', 200.5)],
];

describe('SimulationHAL and PhysicalHAL on the emulated robot', () => {
  it('end every call of the same script with the same result, steps and pose', async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      pty: false,
      hostTimeoutMs: LONGEST_HOST_TIMEOUT_MS, // not a test of the timeout
    });
    const physical = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-agreement',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    const simulated = new SimulationHAL({
      world: new World({ map: { name: 'open', arena: { width: 20, height: 20 } } }),
    });
    try {
      await physical.initialize();
      await simulated.initialize();
      let movesSent = 0;
      for (const [call, run] of SCRIPT) {
        const real = await run(physical);
        const sim = await run(simulated);
        expect(real.success, `${call} on the emulator: ${JSON.stringify(real)}`).toBe(true);
        expect(sim.success, `${call} in simulation: ${JSON.stringify(sim)}`).toBe(true);
        expect(sim.data?.['moves'], call).toEqual(real.data?.['moves']);
        movesSent += typeof real.data?.['moves'] === 'number' ? real.data['moves'] : 1;
        for (const key of ['leftSteps', 'rightSteps', 'leftSps', 'rightSps']) {
          const want = real.data?.[key];
          if (want === undefined) continue;
          expect(
            Math.abs(Number(sim.data?.[key]) - Number(want)),
            `${call}: ${key}`,
          ).toBeLessThanOrEqual(1);
        }
        // The firmware, PhysicalHAL's pose tracker and the simulation integrate the same steps
        // in different groups, so their poses differ by micrometres along arcs; moveTo turns by
        // the angle computed from the HAL's own pose, which can then differ by one step.
        const a = await physical.locomotion.getPose();
        const b = await simulated.locomotion.getPose();
        expect(Math.abs(b.position.x - a.position.x), `${call}: x`).toBeLessThan(0.001);
        expect(Math.abs(b.position.y - a.position.y), `${call}: y`).toBeLessThan(0.001);
        expect(Math.abs(b.rotation.yaw - a.rotation.yaw), `${call}: yaw`).toBeLessThan(0.002);
      }
      // The emulator prints its events on its own stdout, which can arrive after the UDP reply:
      // wait for the line of the last move before reading where the wheels ended.
      const finished = await emulator.waitForCount((e) => e.event === 'move_finished', movesSent);
      expect(finished).toHaveLength(movesSent);
      const last = finished.at(-1);
      expect(
        Math.abs(simulated.robot.leftSteps - Number(last?.['left_position'])),
      ).toBeLessThanOrEqual(2);
      expect(
        Math.abs(simulated.robot.rightSteps - Number(last?.['right_position'])),
      ).toBeLessThanOrEqual(2);
    } finally {
      await physical.cleanup();
      await simulated.cleanup();
      await emulator.stop();
    }
  });
});
