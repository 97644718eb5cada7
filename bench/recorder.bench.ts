// The flight recorder's cost on the robot's path: a PhysicalHAL command round trip (setLED over
// UDP to the emulator) through recordHal, against the same HAL unrecorded, in one run, interleaved
// block by block: p50 and p99 of each and their ratio (goal: within 5 %). The recording goes to a
// real file (zstd chunks) in the temporary folder; the messages it wrote per second of recorded
// calls, and the file's size, are reported beside. RECORDER_ROUNDS sets the calls per side
// (default 6000).
import { mkdtempSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PhysicalHAL } from '@hal/physical';
import { McapRecorder, recordHal } from '@hal/recorder';
import type { HardwareAbstractionLayer } from '@hal/types';
import { startEmulator } from '../tests/physical/emulator.js';
import { percentile, reportFigure } from './report/figures.js';

const ROUNDS = Number(process.env['RECORDER_ROUNDS'] ?? 6000);
const BLOCK = 200;
const WARMUP = 2000;

const fmt = (ms: number) => `${(ms * 1000).toFixed(0)} us`;

async function block(hal: HardwareAbstractionLayer, rounds: number, into: number[]): Promise<void> {
  for (let i = 0; i < rounds; i++) {
    const start = performance.now();
    const result = await hal.communication.setLED(i % 256, 0, 0, 'solid');
    into.push(performance.now() - start);
    if (!result.success) throw new Error(`setLED failed: ${result.error}`);
  }
}

const emulator = await startEmulator({ pty: false });
const dir = mkdtempSync(join(tmpdir(), 'hal-bench-recorder-'));
try {
  const file = join(dir, 'bench.mcap');
  const recorder = await McapRecorder.toFile(file);
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'bench',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
  });
  await hal.initialize();
  // no timed pose sampling, which would load the unrecorded blocks too (the HAL is the same);
  // setLED moves nothing, so no pose is read after it either: each call is one call record
  const recorded = recordHal(hal, recorder, { posePeriodMs: 0 });
  await block(hal, WARMUP, []);
  await block(recorded, WARMUP, []);

  const off: number[] = [];
  const on: number[] = [];
  let recordedMs = 0;
  // the warm-up's records are written before counting (deferred a turn, then queued)
  await new Promise((resolve) => setTimeout(resolve, 50));
  await recorder.drained();
  const writtenBefore = recorder.stats().written;
  for (let done = 0; done < ROUNDS; done += BLOCK) {
    await block(hal, BLOCK, off);
    const started = performance.now();
    await block(recorded, BLOCK, on);
    recordedMs += performance.now() - started;
  }
  await recorder.drained();
  const stats = await recorder.close();
  await hal.cleanup();
  const written = stats.written - writtenBefore;

  const rows = [
    ['p50', percentile(on, 50), percentile(off, 50)],
    ['p99', percentile(on, 99), percentile(off, 99)],
  ] as const;
  console.log(
    `recorder: UDP round trip (setLED) over ${ROUNDS} calls each, interleaved blocks of ${BLOCK}`,
  );
  for (const [name, recordedValue, plain] of rows) {
    const ratio = recordedValue / plain;
    console.log(
      `  ${name}: recorded ${fmt(recordedValue)}, unrecorded ${fmt(plain)} (${ratio.toFixed(3)}x)`,
    );
    reportFigure({
      bench: 'recorder',
      name: `UDP round trip ${name}, recorded`,
      value: recordedValue,
      unit: 'ms',
      better: 'lower',
      alternative: { name: 'the same HAL unrecorded', value: plain },
      goal: '<= 1.05x unrecorded',
      met: ratio <= 1.05,
      note: 'setLED to cube-emulator over UDP on 127.0.0.1, recorded into a zstd MCAP file (one call record per call); the p99 of both moves by several times between runs on a shared 2-core machine',
    });
  }
  const perSecond = written / (recordedMs / 1000);
  const size = statSync(file).size;
  console.log(
    `  ${written} messages written in the recorded blocks (${perSecond.toFixed(0)}/s of recorded calls), ${stats.dropped} dropped; file ${(size / 1024).toFixed(0)} KiB`,
  );
  reportFigure({
    bench: 'recorder',
    name: 'messages recorded per second of recorded calls',
    value: perSecond,
    unit: 'messages/s',
    better: 'higher',
    note: `one call record per setLED; ${stats.dropped} dropped`,
  });
} finally {
  await emulator.stop();
  rmSync(dir, { recursive: true, force: true });
}
