// Which layer of PhysicalHAL adds what to a UDP round trip, and whether its tail follows the work
// it does or the memory it allocates. The same set_led to the same emulator, interleaved in blocks:
//   raw          a node:dgram ping-pong (the reply parsed, its seq checked)
//   raw+cpu      raw spending 8 us more per call in a busy loop (more work, no allocation)
//   raw+alloc    raw allocating about 4 KB more per call (small objects, dropped at once)
//   transport    MessageCodec + the UDP transport (ReplyMatcher: seq match, resend timer)
//   session      + the Session (queue, seq numbers, reply data checked against its schema)
//   hal          + PhysicalHAL (HalBoundary: readiness, e-stop, parameters; the result)
// Per variant: the latency percentiles, the calls above 300 us and the GCs during its calls; with --alloc, the bytes each
// call allocates instead (heap growth over many calls with no GC: run it as below).
// A tool beside udp-trace.ts, not a benchmark of `pnpm bench` (it reports no figures).
//   node --conditions=@hal/source --import tsx bench/udp-layers.ts [--blocks N] [--rounds N]
//   node --expose-gc --max-semi-space-size=256 --min-semi-space-size=256 \
//     --conditions=@hal/source --import tsx bench/udp-layers.ts --alloc
import { randomBytes } from 'node:crypto';
import { PerformanceObserver } from 'node:perf_hooks';
import { parseArgs } from 'node:util';
import { PhysicalHAL, udpTransport } from '@hal/physical';
import { MessageCodec } from '@hal/physical/protocol';
import { Session } from '@hal/physical/testing';
import { silentLogger } from '@hal/types';
import { startEmulator } from '../tests/physical/emulator.js';
import { openRawUdpClient, setLedJson } from './raw-udp-client.js';
import { percentile } from './report/figures.js';

const { values } = parseArgs({
  options: {
    alloc: { type: 'boolean', default: false },
    blocks: { type: 'string', default: '20' },
    rounds: { type: 'string', default: '1000' },
  },
});
const BLOCKS = Number(values.blocks);
const ROUNDS = Number(values.rounds);
const SLOW_MS = 0.3;
const TIMING = { timeoutMs: 500, attempts: 12 };

const emulator = await startEmulator();
const port = emulator.udpPort;

/** Integer work that allocates nothing, calibrated to take about `us` microseconds. */
let spinsPerUs = 0;
let spinSink = 0;
function spin(us: number): void {
  let x = spinSink;
  for (let i = 0; i < us * spinsPerUs; i++) x = (x * 1103515245 + 12345) | 0;
  spinSink = x;
}
{
  spinsPerUs = 1000;
  const start = performance.now();
  spin(10_000);
  spinsPerUs = Math.round((1000 * 10_000) / ((performance.now() - start) * 1000));
}

/** Keeps what raw+alloc allocates reachable until the next call, as a request's objects are. */
let kept: unknown[] = [];

async function raw(rounds: number, extra: { cpuUs?: number; objects?: number } = {}) {
  const client = await openRawUdpClient(port);
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const seq = i + 2;
    const start = performance.now();
    const reply = await client.ask(setLedJson(seq, client.sid, i));
    if (extra.cpuUs !== undefined) spin(extra.cpuUs);
    if (extra.objects !== undefined) {
      kept = [];
      for (let k = 0; k < extra.objects; k++) kept.push({ k, list: [k] });
    }
    samples.push(performance.now() - start);
    if (reply.seq !== seq) throw new Error(`raw: reply seq ${reply.seq}, expected ${seq}`);
  }
  client.close();
  return samples;
}

/** The codec and a UDP transport to the emulator, as PhysicalHAL builds them. */
async function openLink() {
  const codec = new MessageCodec();
  const link = await udpTransport({ host: '127.0.0.1', port }).connect({
    decode: (bytes) => codec.decode(bytes),
    logger: silentLogger,
  });
  return { codec, link };
}

async function transport(rounds: number) {
  const { codec, link } = await openLink();
  const nonce = randomBytes(4).toString('hex');
  const hello = await link.request(1, codec.encode({ cmd: 'hello', seq: 1, nonce }), TIMING);
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const seq = i + 2;
    const start = performance.now();
    const message = {
      cmd: 'set_led',
      seq,
      sid: hello.sid,
      r: i % 256,
      g: 0,
      b: 0,
      pattern: 'solid',
    };
    const reply = await link.request(seq, codec.encode(message), TIMING);
    samples.push(performance.now() - start);
    if (!reply.ok) throw new Error(`transport: set_led refused: ${reply.error?.code}`);
  }
  await link.close();
  return samples;
}

async function session(rounds: number) {
  const { codec, link } = await openLink();
  const open = new Session({
    transport: link,
    codec,
    logger: silentLogger,
    heartbeatIntervalMs: () => 500,
    reconnectIntervalMs: 1000,
    request: () => TIMING,
  });
  await open.open();
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const start = performance.now();
    await open.command('set_led', { r: i % 256, g: 0, b: 0, pattern: 'solid' });
    samples.push(performance.now() - start);
  }
  open.close();
  await link.close();
  return samples;
}

async function hal(rounds: number) {
  const physical = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'layers',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: port },
  });
  await physical.initialize();
  const samples: number[] = [];
  for (let i = 0; i < rounds; i++) {
    const start = performance.now();
    const result = await physical.communication.setLED(i % 256, 0, 0, 'solid');
    samples.push(performance.now() - start);
    if (!result.success) throw new Error(`setLED failed: ${result.error}`);
  }
  await physical.cleanup();
  return samples;
}

const VARIANTS: [string, (rounds: number) => Promise<number[]>][] = [
  ['raw', (n) => raw(n)],
  ['raw+cpu', (n) => raw(n, { cpuUs: 8 })],
  ['raw+alloc', (n) => raw(n, { objects: 32 })],
  ['transport', transport],
  ['session', session],
  ['hal', hal],
];

const us = (ms: number) => `${(ms * 1000).toFixed(1)} us`.padStart(10);

try {
  for (const [, run] of VARIANTS) await run(5000); // warm: JIT compilation off the measured calls
  if (values.alloc) {
    const gc = (globalThis as { gc?: () => void }).gc;
    if (gc === undefined)
      throw new Error('--alloc needs node --expose-gc (see the top of this file)');
    const calls = 20_000;
    console.log(`bytes allocated per call (heap growth over ${calls} calls, no GC):`);
    for (const [name, run] of VARIANTS) {
      gc();
      const before = process.memoryUsage().heapUsed;
      await run(calls);
      const after = process.memoryUsage().heapUsed;
      console.log(`  ${name.padEnd(10)} ${((after - before) / calls).toFixed(0).padStart(6)} B`);
    }
  } else {
    const samples = new Map<string, number[]>(VARIANTS.map(([name]) => [name, []]));
    // the garbage collections during each variant's blocks, and how many ms they took
    const gcs = new Map<string, { count: number; ms: number }>(
      VARIANTS.map(([name]) => [name, { count: 0, ms: 0 }]),
    );
    let running = '';
    const observer = new PerformanceObserver((list) => {
      for (const entry of list.getEntries()) {
        const tally = gcs.get(running);
        if (tally === undefined) continue;
        tally.count += 1;
        tally.ms += entry.duration;
      }
    });
    observer.observe({ entryTypes: ['gc'] });
    for (let block = 0; block < BLOCKS; block++) {
      for (const [name, run] of VARIANTS) {
        running = name;
        samples.get(name)!.push(...(await run(ROUNDS)));
        await new Promise((resolve) => setImmediate(resolve)); // its GC entries are delivered
      }
    }
    observer.disconnect();
    console.log(`${BLOCKS} interleaved blocks of ${ROUNDS} set_led round trips per variant:`);
    for (const [name, s] of samples) {
      const slow = s.filter((ms) => ms > SLOW_MS).length;
      console.log(
        `  ${name.padEnd(10)} p50 ${us(percentile(s, 50))}  p90 ${us(percentile(s, 90))}  p99 ${us(percentile(s, 99))}  p99.9 ${us(percentile(s, 99.9))}  above ${SLOW_MS * 1000} us: ${String(slow).padStart(3)}  GCs: ${gcs.get(name)!.count} (${gcs.get(name)!.ms.toFixed(1)} ms)`,
      );
    }
  }
} finally {
  await emulator.stop();
}
