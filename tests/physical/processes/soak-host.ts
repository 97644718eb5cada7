// A soak host: PhysicalHAL on one link (udp PORT, or serial PTY) runs COUNT cheap commands, a mix
// of status reads, LED changes, zero-speed drives and short moves, as fast as they complete, or
// until MAX_SECONDS have passed. It prints one JSON line when warmed up and one at the end, with
// its resident memory (after a full GC when Node runs with --expose-gc), the latency of the
// single-request calls and what the robot's counters should read.
// usage: soak-host.ts udp|serial PORT|PTY COUNT TIME_SCALE MAX_SECONDS
import { rotationArcCm, StepAccumulator } from '@hal/kinematics';
import { PhysicalHAL } from '@hal/physical';
import type { HALToolResult } from '@hal/types';

const [link, target, countArg, scaleArg, maxArg] = process.argv.slice(2);
const count = Number(countArg);
const timeScale = Number(scaleArg);
const maxMs = Number(maxArg) * 1000;
const WARMUP = Math.min(2000, Math.floor(count / 5));
/** Memory is sampled this often after warm-up, to show whether it levels off. */
const CHECKPOINT = Math.max(1, Math.floor((count - WARMUP) / 8));

const emit = (event: string, data: Record<string, unknown>) =>
  process.stdout.write(`${JSON.stringify({ event, ...data })}\n`);

const gc = (globalThis as { gc?: () => void }).gc;
function memory() {
  gc?.();
  const m = process.memoryUsage();
  return { rss: m.rss, heapUsed: m.heapUsed, external: m.external };
}

function percentile(sorted: number[], p: number): number {
  return sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)] ?? 0;
}

const hal = new PhysicalHAL(
  link === 'udp'
    ? {
        mode: 'physical',
        deviceId: 'cube-soak',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: Number(target) },
      }
    : { mode: 'physical', deviceId: 'cube-soak', connection: { type: 'serial', port: target! } },
  { timeScale },
);
await hal.initialize();

const left = new StepAccumulator();
const right = new StepAccumulator();
let expectedLeft = 0;
let expectedRight = 0;
let motions = 0;
const failures: string[] = [];
let failed = 0;
const latencies: number[] = [];
let start = memory();
let started = performance.now();
let done = 0;

for (let i = 0; i < count && performance.now() - started < maxMs; i++) {
  if (i === WARMUP) {
    start = memory();
    emit('warm', { commands: i, ...start });
    started = performance.now();
  }
  if (i > WARMUP && (i - WARMUP) % CHECKPOINT === 0)
    emit('checkpoint', { commands: i, ...memory() });
  const slot = i % 100;
  const t0 = performance.now();
  let result: HALToolResult;
  let single = true;
  if (slot === 50) {
    result = await hal.locomotion.moveForward(0.2);
    expectedLeft += left.add(0.2);
    expectedRight += right.add(0.2);
    motions += 1;
    single = false;
  } else if (slot === 99) {
    const arc = rotationArcCm(1);
    result = await hal.locomotion.rotate('right', 1);
    expectedLeft += left.add(arc);
    expectedRight += right.add(-arc);
    motions += 1;
    single = false;
  } else if (slot % 12 === 0) {
    result = await hal.locomotion.drive(0, 0);
  } else if (slot % 3 === 0) {
    result = await hal.communication.setLED(i % 256, 0, 255 - (i % 256), 'solid');
  } else {
    result = await hal.refreshStatus().then(
      (): HALToolResult => ({ success: true, timestamp: Date.now(), mode: 'physical' }),
      (error: unknown): HALToolResult => ({
        success: false,
        error: String(error),
        timestamp: Date.now(),
        mode: 'physical',
      }),
    );
  }
  if (single) latencies.push(performance.now() - t0);
  if (!result.success) {
    failed += 1;
    if (failures.length < 10) failures.push(`${i}: ${result.code ?? ''} ${result.error ?? ''}`);
  }
  done = i + 1;
}
const seconds = (performance.now() - started) / 1000;
const status = await hal.refreshStatus();
const transport = hal.transportStats();
const end = memory(); // with the HAL still open: whatever it holds counts
await hal.cleanup();
latencies.sort((a, b) => a - b);
emit('done', {
  commands: done,
  measuredCommands: done - WARMUP,
  seconds,
  perSecond: (done - WARMUP) / seconds,
  p50Ms: percentile(latencies, 50),
  p99Ms: percentile(latencies, 99),
  failures,
  failed,
  start,
  end,
  gc: gc !== undefined,
  motions,
  expected: { left: expectedLeft, right: expectedRight },
  robot: { left: status.left_steps, right: status.right_steps, moveId: status.move_id },
  transport,
});
