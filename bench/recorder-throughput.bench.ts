// Messages the flight recorder writes per second, to a real file: a typical call record (a
// moveTo's arguments, HALToolResult and pose_after, ~600 bytes of JSON) written as fast as the
// recorder takes it, through McapRecorder (zstd chunks, the default) and, interleaved block by
// block in the same run, through the plain alternative a user might write instead: one JSON line
// per message appended to a file through a Node write stream. Each block is timed from its first
// write until the data has been handed to the file (the recorder drained, the stream's callback).
// RECORDER_THROUGHPUT_MESSAGES sets the messages per side (default 200,000).
import { createWriteStream, mkdtempSync, rmSync, statSync } from 'node:fs';
import type { WriteStream } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { CALL_RECORD, McapRecorder, TOPICS } from '@hal/recorder';
import type { HalCallRecord } from '@hal/recorder';
import { reportFigure } from './report/figures.js';

const MESSAGES = Number(process.env['RECORDER_THROUGHPUT_MESSAGES'] ?? 200_000);
const BLOCK = 10_000;

const pose = {
  position: { x: 0.412, y: 0.1875, z: 0 },
  rotation: { yaw: 1.5707, pitch: 0, roll: 0 },
  velocity: { linear: 0, angular: 0 },
  confirmed: true,
};
function record(i: number): HalCallRecord {
  return {
    call: 'locomotion.moveTo',
    args: [0.412, 0.1875 + i * 1e-6, 0],
    outcome: 'resolved',
    success: true,
    result: {
      success: true,
      mode: 'simulation',
      timestamp: 1764547200000 + i,
      executionTime: 2150.4,
      data: { leftSteps: 2207, rightSteps: 2207, distanceM: 0.1016 },
    },
    pose_after: pose,
    start_ns: (1764547200000000000n + BigInt(i) * 1000000n).toString(),
    duration_ms: 2150.4,
  };
}

async function mcapBlock(recorder: McapRecorder, from: number): Promise<number> {
  const started = performance.now();
  for (let i = from; i < from + BLOCK; i++) recorder.write(TOPICS.calls, record(i));
  await recorder.drained();
  return performance.now() - started;
}

async function ndjsonBlock(stream: WriteStream, from: number): Promise<number> {
  const started = performance.now();
  let last: Promise<void> = Promise.resolve();
  for (let i = from; i < from + BLOCK; i++) {
    const line = `${JSON.stringify({ topic: TOPICS.calls, ...record(i) })}\n`;
    if (!stream.write(line)) {
      // as a careful writer does: wait for the stream to drain rather than buffer without bound
      await new Promise<void>((resolve) => stream.once('drain', resolve));
    }
    if (i === from + BLOCK - 1)
      last = new Promise<void>((resolve) => stream.write('', () => resolve()));
  }
  await last;
  return performance.now() - started;
}

const dir = mkdtempSync(join(tmpdir(), 'hal-bench-recorder-throughput-'));
try {
  const mcapFile = join(dir, 'bench.mcap');
  const ndjsonFile = join(dir, 'bench.ndjson');
  // a queue large enough to take a whole block: this measures the writer, not the drop policy
  const recorder = await McapRecorder.toFile(mcapFile, { maxQueuedBytes: 64 * 1024 * 1024 });
  recorder.channel(TOPICS.calls, CALL_RECORD);
  const stream = createWriteStream(ndjsonFile);
  await mcapBlock(recorder, 0); // warm-up
  await ndjsonBlock(stream, 0);
  const writtenBefore = recorder.stats().written;
  let mcapMs = 0;
  let ndjsonMs = 0;
  for (let done = 0; done < MESSAGES; done += BLOCK) {
    mcapMs += await mcapBlock(recorder, BLOCK + done);
    ndjsonMs += await ndjsonBlock(stream, BLOCK + done);
  }
  const stats = await recorder.close();
  await new Promise<void>((resolve) => stream.end(resolve));
  const written = stats.written - writtenBefore;
  if (written !== MESSAGES) throw new Error(`wrote ${written} of ${MESSAGES} messages`);
  const mcapRate = written / (mcapMs / 1000);
  const ndjsonRate = MESSAGES / (ndjsonMs / 1000);
  const mcapSize = statSync(mcapFile).size;
  const ndjsonSize = statSync(ndjsonFile).size;
  console.log(`recorder: ${MESSAGES} call records a side, interleaved in blocks of ${BLOCK}`);
  console.log(
    `  McapRecorder (zstd): ${mcapRate.toFixed(0)} messages/s, ${stats.dropped} dropped, file ${(mcapSize / 1048576).toFixed(1)} MiB`,
  );
  console.log(
    `  JSON lines (write stream): ${ndjsonRate.toFixed(0)} messages/s, file ${(ndjsonSize / 1048576).toFixed(1)} MiB`,
  );
  console.log(
    `  ratio ${(mcapRate / ndjsonRate).toFixed(2)}x the messages/s, ${(mcapSize / ndjsonSize).toFixed(3)}x the size`,
  );
  reportFigure({
    bench: 'recorder-throughput',
    name: 'messages recorded per second (McapRecorder, zstd)',
    value: mcapRate,
    unit: 'messages/s',
    better: 'higher',
    alternative: { name: 'JSON lines through a write stream', value: ndjsonRate },
    note: `a ~600-byte call record each, to a file in the temporary folder, until handed to the file; ${stats.dropped} dropped`,
  });
  reportFigure({
    bench: 'recorder-throughput',
    name: 'file size of the call records (McapRecorder, zstd)',
    value: mcapSize / MESSAGES,
    unit: 'bytes/message',
    better: 'lower',
    alternative: { name: 'JSON lines', value: ndjsonSize / MESSAGES },
    note: 'the zstd MCAP file (with its index) against the uncompressed JSON lines of the same records; records this alike compress better than a real run does (see recorder-size)',
  });
} finally {
  rmSync(dir, { recursive: true, force: true });
}
