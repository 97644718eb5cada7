// Exactly-once over a damaged serial line: PhysicalHAL on a pseudo-terminal whose every frame,
// both ways, may be preceded by garbage, have a bit flipped, or arrive twice (seeded), against
// the emulator. The robot's own counters say how often each command ran.
import { PhysicalHAL } from '@hal/physical';
import { rotationArcCm, StepAccumulator } from '@hal/kinematics';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { startSerialFaultRelay } from './serial-fault-relay.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 10;
const ROUNDS = 30;

describe('PhysicalHAL over a serial line with garbage, bit errors and duplicated frames', () => {
  it(`executes every command exactly once through ${ROUNDS} rounds of moves, LED changes and status reads`, async () => {
    // a long host timeout: a loaded machine must not let the robot stop a move (200 ms real at
    // the default); the host resends every quarter of it (250 ms real), ample for a bad line
    const emulator = await startEmulator({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
    const faults = { garbage: 0.05, bitFlip: 0.02, duplicate: 0.05 };
    const relay = await startSerialFaultRelay({
      robotPty: emulator.pty,
      seed: 20261130,
      toRobot: faults,
      toHost: faults,
    });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-damaged-line',
        connection: { type: 'serial', port: relay.path },
      },
      { timeScale: TIME_SCALE },
    );
    try {
      await hal.initialize();
      const left = new StepAccumulator();
      const right = new StepAccumulator();
      let expectedLeft = 0;
      let expectedRight = 0;
      let motions = 0;
      const failures: string[] = [];
      const check = (what: string, result: { success: boolean; code?: string; error?: string }) => {
        if (!result.success) failures.push(`${what}: ${result.code} ${result.error}`);
      };
      for (let i = 0; i < ROUNDS; i++) {
        check(`forward ${i}`, await hal.locomotion.moveForward(1));
        expectedLeft += left.add(1);
        expectedRight += right.add(1);
        check(`rotate ${i}`, await hal.locomotion.rotate('left', 5));
        const arc = rotationArcCm(5);
        expectedLeft += left.add(-arc);
        expectedRight += right.add(arc);
        motions += 2;
        check(`led ${i}`, await hal.communication.setLED(i, 255 - i, 7, 'solid'));
        const status = await hal.refreshStatus();
        expect(status.move_id).toBe(motions);
        expect(status.led).toEqual({ r: i, g: 255 - i, b: 7, pattern: 'solid' });
      }
      expect(failures).toEqual([]);
      const status = await hal.refreshStatus();
      expect(status.left_steps).toBe(expectedLeft);
      expect(status.right_steps).toBe(expectedRight);
      expect(status.move_id).toBe(motions);
      expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(motions);
      expect(emulator.events.filter((e) => e.event === 'trip')).toEqual([]);
      // the line really was bad, both ways, in every way
      for (const direction of [relay.toRobot, relay.toHost]) {
        expect(direction.garbage).toBeGreaterThan(0);
        expect(direction.bitFlips).toBeGreaterThan(0);
        expect(direction.duplicates).toBeGreaterThan(0);
      }
      const link = hal.linkStats()!;
      expect(link.checksumErrors + link.resyncBytes).toBeGreaterThan(0);
      expect(link.duplicateFrames).toBeGreaterThan(0);
    } finally {
      await hal.cleanup();
      await relay.close();
      await emulator.stop();
    }
  });
});
