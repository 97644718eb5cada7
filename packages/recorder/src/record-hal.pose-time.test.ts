import { SimulationHAL } from '@hal/simulation';
import { describe, expect, it } from 'vitest';
import { memorySink } from './file-sink.js';
import { TOPICS } from './messages.js';
import { readRecording } from './read-recording.js';
import { recordHal } from './record-hal.js';
import { McapRecorder } from './recorder.js';

describe('recordHal', () => {
  it('logs a call, and the pose it left, at the time it answered, not when its record is made later', async () => {
    // The file's clock is set by hand: it jumps far ahead right after the call has answered,
    // before the record (made later, with no call on its way) is written.
    let now = 1_000n;
    const later = 1_000_000_000n;
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink, { clock: () => now });
    const hal = recordHal(new SimulationHAL(), recorder, { posePeriodMs: 0 });
    await hal.initialize();
    const result = await hal.locomotion.moveForward(5);
    expect(result.success).toBe(true);
    now = later;
    const pose = await hal.locomotion.getPose();
    await hal.cleanup();
    await recorder.close();

    const recording = await readRecording(sink.bytes());
    const poses = recording.messages.filter((m) => m.topic === TOPICS.halPose);
    const moved = poses.find(
      (m) => (m.value as { position: { x: number } }).position.x === pose.position.x,
    );
    expect(moved).toBeDefined();
    expect(moved?.logTime).toBeLessThan(later);
    // and so is its call record, though made after the jump
    const call = recording.messages.find(
      (m) =>
        m.topic === TOPICS.calls && (m.value as { call: string }).call === 'locomotion.moveForward',
    );
    expect(call?.logTime).toBe(moved?.logTime);
    expect(BigInt((call?.value as { start_ns: string }).start_ns)).toBeLessThanOrEqual(
      call!.logTime,
    );
  });
});
