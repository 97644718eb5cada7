// Where a PhysicalHAL round trip spends its time, call by call: stamps at the call, at the
// datagram's send, at its reply's arrival in JavaScript, after the reply is decoded and when the
// call resolves; garbage collections (perf_hooks 'gc') and event-loop delay beside them. The slow
// calls (above the p99) are split into those phases and set against the GCs they overlapped, and a
// raw dgram ping-pong to the same emulator, interleaved in blocks, gives the wire's own tail.
// Not a benchmark of `pnpm bench` (it reports no figures): a tool to explain one.
//   node --conditions=@hal/source --import tsx bench/udp-trace.ts [--key] [--rounds N] [--timeline]
// --timeline also prints every call above 0.3 ms, raw (R) and HAL (H), and every GC (G), in time
// order: `<ms since start><R|H|G><duration ms>/<send -> reply ms>`.
import { createHash } from 'node:crypto';
import { Socket } from 'node:dgram';
import { monitorEventLoopDelay, PerformanceObserver } from 'node:perf_hooks';
import type { PerformanceEntry } from 'node:perf_hooks';
import { parseArgs } from 'node:util';
import { PhysicalHAL } from '@hal/physical';
import { MessageCodec } from '@hal/physical/protocol';
import { startEmulator } from '../tests/physical/emulator.js';
import { openRawUdpClient, setLedJson } from './raw-udp-client.js';
import { percentile } from './report/figures.js';

const { values } = parseArgs({
  options: {
    key: { type: 'boolean', default: false },
    rounds: { type: 'string', default: '8000' },
    timeline: { type: 'boolean', default: false },
  },
});
const ROUNDS = Number(values.rounds);
const BLOCKS = 8;
const KEY = values.key ? createHash('sha256').update('bench key').digest('hex') : undefined;

/** The stamps of one call, ms on performance.now(). */
interface Trace {
  call: number;
  send?: number;
  receive?: number;
  decoded?: number;
  resolved: number;
}

let current: Partial<Trace> | undefined;
// stamp the first send, the first arrival and the end of the first decode inside a traced call
const send = Socket.prototype.send;
Socket.prototype.send = function (this: Socket, ...args: unknown[]) {
  if (current !== undefined) current.send ??= performance.now();
  (send as (...a: unknown[]) => void).apply(this, args);
} as typeof Socket.prototype.send;
const emit = Socket.prototype.emit;
Socket.prototype.emit = function (this: Socket, event: string | symbol, ...args: unknown[]) {
  if (event === 'message' && current !== undefined) current.receive ??= performance.now();
  return (emit as (...a: unknown[]) => boolean).apply(this, [event, ...args]);
};
const decode = MessageCodec.prototype.decode;
MessageCodec.prototype.decode = function (this: MessageCodec, bytes: Uint8Array) {
  const result = decode.call(this, bytes);
  if (current !== undefined) current.decoded ??= performance.now();
  return result;
};

const gcs: { start: number; end: number; kind: number }[] = [];
const observer = new PerformanceObserver((list) => {
  for (const entry of list.getEntries() as (PerformanceEntry & { detail?: { kind?: number } })[]) {
    gcs.push({
      start: entry.startTime,
      end: entry.startTime + entry.duration,
      kind: entry.detail?.kind ?? 0,
    });
  }
});
observer.observe({ entryTypes: ['gc'] });

async function halBlock(port: number, rounds: number, traces: Trace[]): Promise<void> {
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'trace',
    connection: {
      type: 'wifi',
      host: '127.0.0.1',
      udpPort: port,
      ...(KEY === undefined ? {} : { key: KEY }),
    },
  });
  await hal.initialize();
  for (let i = 0; i < rounds; i++) {
    current = { call: performance.now() };
    const result = await hal.communication.setLED(i % 256, 0, 0, 'solid');
    const trace = { ...current, resolved: performance.now() } as Trace;
    current = undefined;
    if (!result.success) throw new Error(`setLED failed: ${result.error}`);
    traces.push(trace);
  }
  await hal.cleanup();
}

/** The benchmark's raw client: the same set_led, its reply parsed and its seq checked. */
async function rawBlock(port: number, rounds: number, samples: number[]): Promise<void> {
  const client = await openRawUdpClient(port);
  for (let i = 0; i < rounds; i++) {
    const seq = i + 2;
    const json = setLedJson(seq, client.sid, i);
    const start = performance.now();
    const reply = await client.ask(json);
    samples.push(performance.now() - start);
    rawStarts.push(start);
    if (reply.seq !== seq) throw new Error(`raw: reply seq ${reply.seq}, expected ${seq}`);
  }
  client.close();
}

const rawStarts: number[] = [];
const us = (ms: number) => `${(ms * 1000).toFixed(1).padStart(7)} us`;

const emulator = await startEmulator(KEY === undefined ? {} : { key: KEY });
const delay = monitorEventLoopDelay({ resolution: 1 });
try {
  const warm: Trace[] = [];
  await halBlock(emulator.udpPort, 500, warm);
  await rawBlock(emulator.udpPort, 500, []);
  const traces: Trace[] = [];
  const raw: number[] = [];
  gcs.length = 0;
  delay.enable();
  const cpu = { raw: 0, hal: 0 };
  const cpuOf = async (run: () => Promise<void>) => {
    const before = process.cpuUsage();
    await run();
    const used = process.cpuUsage(before);
    return (used.user + used.system) / 1000;
  };
  for (let block = 0; block < BLOCKS; block++) {
    if (KEY === undefined)
      cpu.raw += await cpuOf(() => rawBlock(emulator.udpPort, ROUNDS / BLOCKS, raw));
    cpu.hal += await cpuOf(() => halBlock(emulator.udpPort, ROUNDS / BLOCKS, traces));
  }
  delay.disable();
  const total = traces.map((t) => t.resolved - t.call);
  const p99 = percentile(total, 99);
  const phases = (t: Trace) => ({
    'call -> send': (t.send ?? t.call) - t.call,
    'send -> reply in JS': (t.receive ?? t.resolved) - (t.send ?? t.call),
    'reply -> decoded': (t.decoded ?? t.resolved) - (t.receive ?? t.resolved),
    'decoded -> resolved': t.resolved - (t.decoded ?? t.resolved),
  });
  const overlapsGc = (t: Trace) => gcs.some((g) => g.start < t.resolved && g.end > t.call);
  const describe = (label: string, set: Trace[]) => {
    console.log(`${label} (${set.length} calls):`);
    for (const name of Object.keys(phases(set[0]!)) as (keyof ReturnType<typeof phases>)[]) {
      const values = set.map((t) => phases(t)[name]);
      console.log(
        `  ${name.padEnd(22)} p50 ${us(percentile(values, 50))}  p99 ${us(percentile(values, 99))}  max ${us(Math.max(...values))}`,
      );
    }
    const withGc = set.filter(overlapsGc).length;
    console.log(`  overlapping a GC: ${withGc} (${((100 * withGc) / set.length).toFixed(1)} %)`);
  };
  console.log(`PhysicalHAL set_led, ${traces.length} calls${KEY === undefined ? '' : ', keyed'}:`);
  console.log(
    `  total p50 ${us(percentile(total, 50))}  p99 ${us(p99)}  p99.9 ${us(percentile(total, 99.9))}`,
  );
  if (raw.length > 0) {
    console.log(
      `raw dgram set_led:   p50 ${us(percentile(raw, 50))}  p99 ${us(percentile(raw, 99))}  p99.9 ${us(percentile(raw, 99.9))}`,
    );
  }
  console.log(
    `CPU time of this process per call (all threads): raw ${us(cpu.raw / Math.max(1, raw.length))}, PhysicalHAL ${us(cpu.hal / traces.length)}`,
  );
  describe('all calls', traces);
  if (values.timeline) {
    const t0 = traces[0]!.call;
    const events = [
      ...traces
        .filter((t) => t.resolved - t.call > 0.3)
        .map(
          (t) => [t.call - t0, 'H', t.resolved - t.call, (t.receive ?? 0) - (t.send ?? 0)] as const,
        ),
      ...raw.map((ms, i) => [rawStarts[i]! - t0, 'R', ms, ms] as const).filter((e) => e[2] > 0.3),
      ...gcs.map((g) => [g.start - t0, 'G', g.end - g.start, 0] as const),
    ].sort((a, b) => a[0] - b[0]);
    console.log(
      events.map((e) => `${e[0].toFixed(1)}${e[1]}${e[2].toFixed(2)}/${e[3].toFixed(2)}`).join(' '),
    );
    const perBlock = ROUNDS / BLOCKS;
    console.log(
      'slow call indices within a block:',
      traces
        .map((t, i) => [i % perBlock, t.resolved - t.call] as const)
        .filter(([, ms]) => ms > p99)
        .map(([i, ms]) => `${i}:${(ms * 1000).toFixed(0)}`)
        .join(' '),
    );
  }
  describe(
    'calls above the p99',
    traces.filter((t) => t.resolved - t.call > p99),
  );
  const gcTime = gcs.reduce((sum, g) => sum + (g.end - g.start), 0);
  console.log(
    `GCs during the run: ${gcs.length} (${gcs.filter((g) => g.kind === 1).length} minor), ${gcTime.toFixed(1)} ms in all; ` +
      `per call ${((gcTime / traces.length) * 1000).toFixed(2)} us`,
  );
  console.log(
    `event-loop delay (1 ms resolution): p50 ${(delay.percentile(50) / 1e3).toFixed(0)} us, p99 ${(delay.percentile(99) / 1e3).toFixed(0)} us, max ${(delay.max / 1e3).toFixed(0)} us`,
  );
} finally {
  observer.disconnect();
  await emulator.stop();
}
