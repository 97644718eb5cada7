import { mkdtemp, readFile, rm } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
import { CALL_RECORD, TOPICS } from './messages.js';
import { readRecording } from './read-recording.js';
import { McapRecorder } from './recorder.js';
import { expectWellFormed } from './validate.fixture.js';

let dir = '';
beforeEach(async () => {
  dir = await mkdtemp(join(tmpdir(), 'hal-worker-writer-'));
});
afterEach(async () => {
  await rm(dir, { recursive: true, force: true });
});

const record = (n: number) => ({
  call: 'locomotion.stop',
  args: [n],
  outcome: 'resolved',
  success: true,
  start_ns: String(n),
  duration_ms: 1,
});

describe('McapRecorder.toFile on a worker thread', () => {
  it('writes the file from a worker by default: every message, in order, well formed', async () => {
    const path = join(dir, 'run.mcap');
    const recorder = await McapRecorder.toFile(path, { chunkSize: 2048 });
    expect(recorder.thread).toBe('worker');
    recorder.channel(TOPICS.calls, CALL_RECORD);
    for (let i = 0; i < 3000; i += 1) recorder.write(TOPICS.calls, record(i), BigInt(i + 1));
    recorder.metadata('hal.test', { run: 'worker' });
    const stats = await recorder.close();
    expect(stats).toEqual({ written: 3000, dropped: 0, queuedBytes: 0 });
    const recording = await readRecording(new Uint8Array(await readFile(path)));
    expectWellFormed(recording);
    const calls = recording.messages.filter((m) => m.topic === TOPICS.calls);
    expect(calls.map((m) => (m.value as { args: number[] }).args[0])).toEqual(
      Array.from({ length: 3000 }, (_, i) => i),
    );
    expect(recording.chunkCount).toBeGreaterThan(10);
    expect(recording.metadata.get('hal.test')).toEqual({ run: 'worker' });
  });

  it('writes the same messages on the caller thread when asked', async () => {
    const path = join(dir, 'caller.mcap');
    const recorder = await McapRecorder.toFile(path, { thread: 'caller' });
    expect(recorder.thread).toBe('caller');
    recorder.channel(TOPICS.calls, CALL_RECORD);
    recorder.write(TOPICS.calls, record(1), 1n);
    await recorder.close();
    const recording = await readRecording(new Uint8Array(await readFile(path)));
    expect(recording.messages.filter((m) => m.topic === TOPICS.calls)).toHaveLength(1);
  });

  it('refuses a file it cannot open, on either thread, naming the cause', async () => {
    const path = join(dir, 'no-such-folder', 'run.mcap');
    await expect(McapRecorder.toFile(path)).rejects.toThrow(/ENOENT/);
    await expect(McapRecorder.toFile(path, { thread: 'caller' })).rejects.toThrow(/ENOENT/);
  });
});
