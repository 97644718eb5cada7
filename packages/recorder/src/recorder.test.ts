import { describe, expect, it } from 'vitest';
import type { RecordingSink } from './file-sink.js';
import { memorySink } from './file-sink.js';
import { CALL_RECORD, TOPICS } from './messages.js';
import { readRecording } from './read-recording.js';
import { McapRecorder } from './recorder.js';
import { expectWellFormed } from './testing/well-formed.js';

function call(n: number): Record<string, unknown> {
  return {
    call: 'locomotion.stop',
    args: [],
    outcome: 'resolved',
    success: true,
    start_ns: String(n),
    duration_ms: 1,
  };
}

/** A sink whose writes wait until released, as a disk that has stalled. */
function stalledSink(): RecordingSink & { release(): void; bytes(): Uint8Array; writes: number } {
  const inner = memorySink();
  let release: () => void = () => undefined;
  const gate = new Promise<void>((resolve) => (release = resolve));
  const sink = {
    writes: 0,
    position: () => inner.position(),
    async write(buffer: Uint8Array) {
      sink.writes += 1;
      await gate;
      await inner.write(buffer);
    },
    close: () => inner.close(),
    release: () => release(),
    bytes: () => inner.bytes(),
  };
  return sink;
}

describe('McapRecorder', () => {
  it('writes a chunked, zstd-compressed file with a summary and index that reads back', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink, { chunkSize: 1024 });
    recorder.channel(TOPICS.calls, CALL_RECORD);
    for (let n = 0; n < 200; n += 1) recorder.write(TOPICS.calls, call(n));
    const stats = await recorder.close();
    // the 200 and the recorder's own /recorder/loss
    expect(stats).toMatchObject({ written: 201, dropped: 0 });

    const recording = await readRecording(sink.bytes());
    expect(recording.complete).toBe(true);
    expect(recording.chunkCount).toBeGreaterThan(1);
    expect(recording.channels.get(TOPICS.calls)).toMatchObject({
      schemaName: 'hal.CallRecord',
      messageCount: 200,
    });
    expect(recording.messages.filter((m) => m.topic === TOPICS.calls).map((m) => m.value)).toEqual(
      Array.from({ length: 200 }, (_, n) => call(n)),
    );
    expect(recording.metadata.get('recorder.loss')).toEqual({ written: '201', dropped: '0' });
    expectWellFormed(recording);
    // zstd, against the same messages uncompressed
    const sizes: Record<string, number> = {};
    for (const compression of ['zstd', 'none'] as const) {
      const plain = memorySink();
      const again = await McapRecorder.create(plain, { compression });
      again.channel(TOPICS.calls, CALL_RECORD);
      for (let n = 0; n < 2000; n += 1) again.write(TOPICS.calls, call(n));
      await again.close();
      sizes[compression] = plain.bytes().byteLength;
      expect((await readRecording(plain.bytes())).messages).toHaveLength(2001);
    }
    expect(sizes['zstd']).toBeLessThan(sizes['none']! / 4);
  });

  it('closes a chunk on time, not only when full: the file holds its messages before close', async () => {
    const sink = memorySink();
    // the default chunk interval (500 ms); 3 small messages are far from the 64 KiB chunk size
    const recorder = await McapRecorder.create(sink);
    recorder.channel(TOPICS.calls, CALL_RECORD);
    for (let n = 0; n < 3; n += 1) recorder.write(TOPICS.calls, call(n));
    const callsOnDisk = async (): Promise<unknown[]> => {
      const bytes = sink.bytes();
      const recording = await readRecording(bytes).catch(() => undefined);
      return recording?.messages.map((m) => m.value) ?? [];
    };
    await expect
      .poll(callsOnDisk, { timeout: 10_000, interval: 50 })
      .toEqual([call(0), call(1), call(2)]);
    // read while the recorder is still open: a file with no summary yet, every message in it
    const open = await readRecording(sink.bytes());
    expect(open.complete).toBe(false);
    expect(open.gaps).toEqual([
      {
        kind: 'cut-short',
        offset: sink.bytes().byteLength,
        reason: 'no summary after it: its writer never finished the file',
      },
    ]);
    expect(open.truncation).toMatch(
      /^cut short after its last complete record, at byte \d+ \(no summary after it: its writer never finished the file\); \d+ records read$/,
    );
    await recorder.close();
    expect((await readRecording(sink.bytes())).complete).toBe(true);
  });

  it('counts every message the file holds in written, its own loss record too', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    recorder.channel(TOPICS.calls, CALL_RECORD);
    for (let n = 0; n < 7; n += 1) recorder.write(TOPICS.calls, call(n));
    const stats = await recorder.close();
    const recording = await readRecording(sink.bytes());
    expect(recording.messages).toHaveLength(8);
    expect(stats.written).toBe(recording.messages.length);
    const loss = recording.messages.find((m) => m.topic === TOPICS.loss);
    expect(loss?.value).toMatchObject({ written: 8, dropped: 0 });
    expect(recording.metadata.get('recorder.loss')).toEqual({ written: '8', dropped: '0' });
  });

  it('never waits for a stalled disk: it drops what does not fit, counts it, logs it and says so in the file', async () => {
    const sink = stalledSink();
    const warnings: string[] = [];
    const recorder = await McapRecorder.create(sink, {
      compression: 'none',
      chunkSize: 256,
      maxQueuedBytes: 4096,
      logger: { log: (level, _namespace, message) => level === 'warn' && warnings.push(message) },
    });
    recorder.channel(TOPICS.calls, CALL_RECORD);
    const before = performance.now();
    for (let n = 0; n < 500; n += 1) recorder.write(TOPICS.calls, call(n));
    // every write returned while the disk had not taken a byte
    expect(sink.position()).toBe(0n);
    expect(performance.now() - before).toBeLessThan(1000);
    const dropped = recorder.stats().dropped;
    expect(dropped).toBeGreaterThan(400);
    expect(warnings.some((w) => w.includes('disk is behind'))).toBe(true);

    sink.release();
    const stats = await recorder.close();
    // the 500, and the loss record written after them
    expect(stats.written + stats.dropped).toBe(501);
    const recording = await readRecording(sink.bytes());
    expect(recording.metadata.get('recorder.loss')).toMatchObject({
      written: String(stats.written),
      dropped: String(stats.dropped),
    });
    const loss = recording.messages.find((m) => m.topic === TOPICS.loss);
    expect(loss?.value).toMatchObject({
      dropped: stats.dropped,
      reason: expect.stringContaining('disk is behind'),
    });
    expect(warnings.some((w) => w.includes(`${stats.dropped} messages dropped`))).toBe(true);
  });

  it('goes on when the disk fails: the failure is logged and every later message counted as dropped', async () => {
    let writes = 0;
    const failing: RecordingSink = {
      position: () => BigInt(writes),
      write: () => {
        writes += 1;
        return writes > 1
          ? Promise.reject(new Error('ENOSPC: no space left on device'))
          : Promise.resolve();
      },
      close: () => Promise.resolve(),
    };
    const warnings: string[] = [];
    const recorder = await McapRecorder.create(failing, {
      compression: 'none',
      chunkSize: 128,
      logger: { log: (level, _namespace, message) => level === 'warn' && warnings.push(message) },
    });
    recorder.channel(TOPICS.calls, CALL_RECORD);
    for (let n = 0; n < 50; n += 1) recorder.write(TOPICS.calls, call(n));
    await recorder.drained();
    const stats = await recorder.close();
    expect(stats.failure).toContain('ENOSPC');
    expect(stats.dropped).toBeGreaterThan(0);
    expect(stats.written + stats.dropped).toBe(50);
    expect(warnings.some((w) => w.includes('ENOSPC') && w.includes('the robot goes on'))).toBe(
      true,
    );
  });

  it('writes nothing while a recorded call is on its way, and writes once it has answered', async () => {
    const sink = memorySink();
    const recorder = await McapRecorder.create(sink);
    recorder.channel(TOPICS.calls, CALL_RECORD);
    await recorder.drained();
    const before = sink.position();
    const answered = recorder.callStarted();
    recorder.write(TOPICS.calls, call(1));
    recorder.defer(() => recorder.write(TOPICS.calls, call(2)));
    await new Promise((resolve) => setTimeout(resolve, 60));
    expect(recorder.stats().written).toBe(0);
    expect(sink.position()).toBe(before);
    answered();
    await expect.poll(() => recorder.stats().written, { timeout: 2000, interval: 5 }).toBe(2);
    await recorder.close();
    const recording = await readRecording(sink.bytes());
    expect(recording.messages.filter((m) => m.topic === TOPICS.calls).map((m) => m.value)).toEqual([
      call(1),
      call(2),
    ]);
  });

  it('holds its work from callBegan to callEnded, as from callStarted to its answer', async () => {
    const recorder = await McapRecorder.create(memorySink());
    recorder.channel(TOPICS.calls, CALL_RECORD);
    await recorder.drained();
    recorder.callBegan();
    recorder.defer(() => recorder.write(TOPICS.calls, call(1)));
    await new Promise((resolve) => setTimeout(resolve, 60));
    expect(recorder.stats().written).toBe(0);
    recorder.callEnded(0.05);
    await expect.poll(() => recorder.stats().written, { timeout: 2000, interval: 5 }).toBe(1);
    await recorder.close();
  });

  it('refuses a maxHoldMs that is not a finite number of ms >= 0 with INVALID_PARAMETER', async () => {
    for (const maxHoldMs of [-1, Number.NaN, Number.POSITIVE_INFINITY]) {
      await expect(McapRecorder.create(memorySink(), { maxHoldMs })).rejects.toMatchObject({
        code: 'INVALID_PARAMETER',
        message: expect.stringContaining('maxHoldMs'),
      });
    }
  });

  it('drops, and counts, a message on a topic never declared and one that cannot be encoded', async () => {
    const recorder = await McapRecorder.create(memorySink());
    recorder.write('/nowhere', { a: 1 });
    recorder.channel(TOPICS.calls, CALL_RECORD);
    recorder.write(TOPICS.calls, { big: 1n });
    expect((await recorder.close()).dropped).toBe(2);
  });
});
