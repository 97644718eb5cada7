// A recorded PhysicalHAL over a lossy UDP link to the emulated cube: the robot's reported step
// counters go to /hal/steps and the link's round trips, resends and RTT to /hal/link, each with
// its schema, and the last of each is what the HAL itself reports as the recording ends.
import { PhysicalHAL } from '@hal/physical';
import { McapRecorder, memorySink, readRecording, recordHal, TOPICS } from '@hal/recorder';
import type { LinkStats, WheelSteps } from '@hal/recorder';
import { afterAll, describe, expect, it } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startFaultProxy } from '../physical/fault-proxy.js';
import { expectWellFormed } from './well-formed.js';

afterAll(stopAllEmulators);

const TIME_SCALE = 20;

describe('recording a PhysicalHAL', () => {
  it("records the robot's reported step counters and the link's statistics, resends included", async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: 10_000,
      pty: false,
    });
    // seeded loss both ways, so some requests are resent and the figures have something to count
    const faults = { drop: 0.2 };
    const proxy = await startFaultProxy({
      robotPort: emulator.udpPort,
      seed: 2026_12_01,
      toRobot: faults,
      toHost: faults,
    });
    const inner = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-link',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: proxy.port },
      },
      { timeScale: TIME_SCALE, requestTimeoutMs: 20 },
    );
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    const hal = recordHal(inner, recorder, { posePeriodMs: 20, linkPeriodMs: 50 });
    let endSteps: WheelSteps;
    let endLink: ReturnType<PhysicalHAL['transportStats']>;
    try {
      await hal.initialize();
      for (let i = 0; i < 6; i++) {
        const result =
          i % 2 === 0
            ? await hal.locomotion.moveForward(2)
            : await hal.locomotion.rotate('left', 30);
        expect(result, `move ${i}: ${result.error}`).toMatchObject({ success: true });
      }
      // the counters as the robot has them now, asked outside the recorded calls
      const status = await inner.refreshStatus();
      endSteps = {
        left_steps: status.left_steps,
        right_steps: status.right_steps,
        left_steps_per_s: 0,
        right_steps_per_s: 0,
        robot_uptime_ms: status.uptime_ms,
      };
      endLink = inner.transportStats();
      await hal.cleanup();
    } finally {
      await inner.cleanup();
      await proxy.close();
      await emulator.stop();
    }
    await recorder.close();

    const recording = await readRecording(sink.bytes());
    expectWellFormed(recording);
    expect(recording.channels.get(TOPICS.steps)?.schemaName).toBe('hal.WheelSteps');
    expect(recording.channels.get(TOPICS.link)?.schemaName).toBe('hal.LinkStats');

    const steps = recording.messages
      .filter((m) => m.topic === TOPICS.steps)
      .map((m) => m.value as WheelSteps);
    // a report per status the robot sent while the motions ran, not one per sample
    expect(steps.length).toBeGreaterThan(6);
    expect(steps.at(-1)).toEqual(endSteps);
    // 3 x 2 cm forward and 3 x 30 degrees left: the right wheel has gone further than the left
    expect(endSteps.right_steps).toBeGreaterThan(endSteps.left_steps);
    expect(endSteps.right_steps).toBeGreaterThan(1000);

    const link = recording.messages
      .filter((m) => m.topic === TOPICS.link)
      .map((m) => m.value as LinkStats);
    expect(link.length).toBeGreaterThan(2);
    const last = link.at(-1)!;
    expect(endLink).toBeDefined();
    expect(last).toMatchObject({
      link_state: 'connected',
      sent: endLink!.sent,
      received: endLink!.received,
      retries: endLink!.retries,
      timeouts: endLink!.timeouts,
    });
    expect(last.retries).toBeGreaterThan(0);
    expect(last.unanswered).toBe(endLink!.sent - endLink!.received);
    expect(last.unanswered).toBeGreaterThan(0);
    expect(last.rtt_p50_ms).toBeGreaterThan(0);
    expect(last.serial).toBeUndefined();
    // the counts only grow through the run
    for (let i = 1; i < link.length; i++)
      expect(link[i]!.sent).toBeGreaterThanOrEqual(link[i - 1]!.sent);
  }, 60_000);
});
