// Exactly-once over a bad network: PhysicalHAL through a seeded fault-injecting proxy.
import { PhysicalHAL } from '@hal/physical';
import { rotationArcCm, StepAccumulator } from '@hal/kinematics';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import { startFaultProxy } from './fault-proxy.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 30;
const MOVES = 200;

describe('PhysicalHAL over a lossy UDP link', () => {
  it(`executes ${MOVES} moves exactly once each at 30% loss and 10% duplication, and the final step counts are exact`, async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: 10_000,
      pty: false,
    });
    const faults = { drop: 0.3, duplicate: 0.1, maxDelayMs: 4, reorder: 0.05 };
    const proxy = await startFaultProxy({
      robotPort: emulator.udpPort,
      seed: 20261123,
      toRobot: faults,
      toHost: faults,
    });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-lossy',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: proxy.port },
      },
      { timeScale: TIME_SCALE, requestTimeoutMs: 20 },
    );
    try {
      await hal.initialize();
      const left = new StepAccumulator();
      const right = new StepAccumulator();
      let expectedLeft = 0;
      let expectedRight = 0;
      const failures: string[] = [];
      for (let i = 0; i < MOVES; i++) {
        let result;
        if (i % 2 === 0) {
          result = await hal.locomotion.moveForward(1);
          expectedLeft += left.add(1);
          expectedRight += right.add(1);
        } else {
          result = await hal.locomotion.rotate('left', 5);
          const arc = rotationArcCm(5);
          expectedLeft += left.add(-arc);
          expectedRight += right.add(arc);
        }
        if (!result.success) failures.push(`move ${i}: ${result.code} ${result.error}`);
      }
      expect(failures).toEqual([]);
      const status = await hal.refreshStatus();
      expect(status.left_steps).toBe(expectedLeft);
      expect(status.right_steps).toBe(expectedRight);
      expect(emulator.events.filter((e) => e.event === 'move_started')).toHaveLength(MOVES);
      expect(emulator.events.filter((e) => e.event === 'trip')).toEqual([]);
      // the link really was bad, both ways
      for (const direction of [proxy.toRobot, proxy.toHost]) {
        expect(direction.dropped).toBeGreaterThan(0.2 * direction.received);
        expect(direction.duplicated).toBeGreaterThan(0.05 * direction.received);
        expect(direction.reordered).toBeGreaterThan(0);
      }
      const stats = hal.transportStats()!;
      expect(stats.retries).toBeGreaterThan(0);
      expect(stats.dropped).toBeGreaterThan(0);
      expect(stats.timeouts).toBe(0);
    } finally {
      await hal.cleanup();
      await proxy.close();
      await emulator.stop();
    }
  });
});
