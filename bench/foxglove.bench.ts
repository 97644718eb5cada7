// The live view's cost to the robot. The emulated cube (cube-emulator) over UDP through
// PhysicalHAL, served live by serveFoxglove; blocks of setLED round trips, interleaved:
//   1. a Foxglove viewer connected and subscribed to every topic, beside no viewer;
//   2. a stalled viewer (its socket not read, as on a link that stopped) beside a viewer that
//      reads, each block with a chatty agent's log line per call, so the stalled one's queue
//      fills and its messages are dropped: the call latency, and the drops counted;
//   3. pose to viewer: from the moment the server read the pose to the moment the viewer has the
//      message, over 127.0.0.1 in this process, p50 and p99.
// Viewers are the real @foxglove/ws-protocol client (tests/foxglove/viewer.ts).
import { serveFoxglove } from '@hal/foxglove';
import { PhysicalHAL } from '@hal/physical';
import { startEmulator } from '../tests/physical/emulator.js';
import { connectViewer } from '../tests/foxglove/viewer.js';
import type { Viewer } from '../tests/foxglove/viewer.js';
import { percentile, reportFigure } from './report/figures.js';

const BLOCKS = 10;
const CALLS_PER_BLOCK = 1000;
const WARMUP = 2000;
const ALL_TOPICS = ['/hal/pose', '/tf', '/hal/pose/raw', '/hal/log', '/hal/safety', '/hal/link'];
const LOG_LINE = 'x'.repeat(8 * 1024);
const POSES = 500;

const fmt = (ms: number) => `${(ms * 1000).toFixed(0)} us`;

const emulator = await startEmulator();
const hal = new PhysicalHAL({
  mode: 'physical',
  deviceId: 'bench',
  connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
});
await hal.initialize();
// the pose at 50 Hz: more load on the robot's process than the default 10
const live = await serveFoxglove(hal, { port: 0, poseRateHz: 50, linkRateHz: 10 });
const robot = live.hal;

async function block(samples: number[], log: boolean): Promise<void> {
  for (let i = 0; i < CALLS_PER_BLOCK; i++) {
    const start = performance.now();
    const result = await robot.communication.setLED(i % 256, 0, 0, 'solid');
    samples.push(performance.now() - start);
    if (!result.success) throw new Error(`setLED failed: ${result.error}`);
    if (log) robot.communication.log(`${i} ${LOG_LINE}`, 'info');
  }
}

async function watcher(): Promise<Viewer> {
  const viewer = await connectViewer(live.url);
  await viewer.subscribe(...ALL_TOPICS.filter((t) => viewer.channels.some((c) => c.topic === t)));
  return viewer;
}

// warm up the HAL and the server's paths
await block([], false);
for (let i = 0; i * CALLS_PER_BLOCK < WARMUP; i++) {
  const v = await watcher();
  await block([], true);
  v.close();
}

// --- 1. a viewer connected beside none ---
const none: number[] = [];
const watched: number[] = [];
for (let b = 0; b < BLOCKS * 2; b++) {
  const withViewer = b % 2 === (Math.floor(b / 2) % 2 === 0 ? 0 : 1);
  if (!withViewer) {
    await block(none, false);
    continue;
  }
  const viewer = await watcher();
  await block(watched, false);
  viewer.close();
}
const n50 = percentile(none, 50);
const w50 = percentile(watched, 50);
const n99 = percentile(none, 99);
const w99 = percentile(watched, 99);
console.log(
  `UDP round trip (setLED): viewer p50 ${fmt(w50)} p99 ${fmt(w99)} | none p50 ${fmt(n50)} p99 ${fmt(n99)} | ` +
    `ratio p50 ${(w50 / n50).toFixed(3)}, p99 ${(w99 / n99).toFixed(3)} (${watched.length} calls each)`,
);
for (const [stat, value, base] of [
  ['p50', w50, n50],
  ['p99', w99, n99],
] as const) {
  reportFigure({
    bench: 'foxglove',
    name: `UDP round trip with a viewer subscribed to every topic ${stat}`,
    value: value * 1000,
    unit: 'us',
    better: 'lower',
    alternative: { name: `UDP round trip with no viewer ${stat}`, value: base * 1000 },
    ...(stat === 'p50' ? { goal: '<= 1.05x no viewer', met: w50 <= n50 * 1.05 } : {}),
  });
}

// --- 3. pose to viewer: idle, and while calls run ---
async function poseLatencies(busy: boolean): Promise<number[]> {
  const viewer = await connectViewer(live.url);
  await viewer.subscribe('/hal/pose');
  const calls = (async () => {
    while (busy && viewer.on('/hal/pose').length < POSES) await block([], false);
  })();
  await viewer.until(() => viewer.on('/hal/pose').length >= POSES);
  await calls;
  viewer.close();
  return viewer.on('/hal/pose').map((m) => m.receivedAtMs - Number(m.at) / 1e6);
}
for (const busy of [false, true]) {
  const latency = await poseLatencies(busy);
  const when = busy ? 'while calls run' : 'idle';
  const l50 = percentile(latency, 50);
  const l99 = percentile(latency, 99);
  console.log(
    `pose to viewer, ${when}: p50 ${fmt(l50)} p99 ${fmt(l99)} (${latency.length} poses at 50 Hz)`,
  );
  for (const [stat, value] of [
    ['p50', l50],
    ['p99', l99],
  ] as const) {
    reportFigure({
      bench: 'foxglove',
      name: `pose to viewer ${when} ${stat}`,
      value: value * 1000,
      unit: 'us',
      better: 'lower',
      note: 'from the server holding the pose to the viewer holding the message; viewer in the same process, over 127.0.0.1',
    });
  }
}

// --- 2. a stalled viewer beside one that reads, a log line per call ---
const reading: number[] = [];
const stalled: number[] = [];
const dropsBefore = live.stats().dropped;
for (let b = 0; b < BLOCKS * 2; b++) {
  const stall = b % 2 === (Math.floor(b / 2) % 2 === 0 ? 0 : 1);
  const viewer = await watcher();
  if (stall) {
    // ws keeps its TCP socket in _socket: the stalled viewer stops reading it
    (viewer.socket as unknown as { _socket: { pause(): void } })._socket.pause();
  }
  await block(stall ? stalled : reading, true);
  viewer.close();
}
const dropped = live.stats().dropped - dropsBefore;
const r50 = percentile(reading, 50);
const s50 = percentile(stalled, 50);
const r99 = percentile(reading, 99);
const s99 = percentile(stalled, 99);
console.log(
  `UDP round trip, a log line a call: stalled viewer p50 ${fmt(s50)} p99 ${fmt(s99)} | reading viewer p50 ${fmt(r50)} p99 ${fmt(r99)} | ` +
    `ratio p50 ${(s50 / r50).toFixed(3)}, p99 ${(s99 / r99).toFixed(3)}; ${dropped} messages dropped for the stalled viewer`,
);
for (const [stat, value, base] of [
  ['p50', s50, r50],
  ['p99', s99, r99],
] as const) {
  reportFigure({
    bench: 'foxglove',
    name: `UDP round trip with a stalled viewer ${stat}`,
    value: value * 1000,
    unit: 'us',
    better: 'lower',
    alternative: { name: `UDP round trip with a viewer that reads ${stat}`, value: base * 1000 },
    note: `an 8 KiB log line per call; ${dropped} messages dropped for the stalled viewer`,
  });
}

await live.close();
await hal.cleanup();
await emulator.stop();
