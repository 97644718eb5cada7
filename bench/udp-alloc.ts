// Bytes allocated per PhysicalHAL round trip (setLED over UDP to cube-emulator, keyless and
// keyed): the young generation is made large enough that no GC runs while it counts, so the
// growth of the heap over the calls is what they allocated. A tool beside udp-trace.ts, not a
// benchmark of `pnpm bench`.
//   node --expose-gc --max-semi-space-size=128 --min-semi-space-size=128 --conditions=@hal/source --import tsx bench/udp-alloc.ts
import { createHash } from 'node:crypto';
import { PerformanceObserver } from 'node:perf_hooks';
import { PhysicalHAL } from '@hal/physical';
import { startEmulator } from '../tests/physical/emulator.js';

const WARMUP = 20_000;
const CALLS = 5_000;
const KEY = createHash('sha256').update('bench key').digest('hex');
const exposedGc = (globalThis as { gc?: () => void }).gc;
if (exposedGc === undefined) throw new Error('run with --expose-gc');
const gc: () => void = exposedGc;

async function bytesPerCall(key?: string): Promise<{ bytes: number; gcs: number }> {
  const emulator = await startEmulator(key === undefined ? {} : { key });
  const hal = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'alloc',
    connection: {
      type: 'wifi',
      host: '127.0.0.1',
      udpPort: emulator.udpPort,
      ...(key === undefined ? {} : { key }),
    },
  });
  try {
    await hal.initialize();
    const run = async (n: number) => {
      for (let i = 0; i < n; i++) {
        const result = await hal.communication.setLED(i % 256, 0, 0, 'solid');
        if (!result.success) throw new Error(`setLED failed: ${result.error}`);
      }
    };
    await run(WARMUP);
    let gcs = 0;
    const observer = new PerformanceObserver((list) => (gcs += list.getEntries().length));
    gc();
    observer.observe({ entryTypes: ['gc'] });
    const before = process.memoryUsage().heapUsed;
    await run(CALLS);
    const after = process.memoryUsage().heapUsed;
    observer.disconnect();
    return { bytes: (after - before) / CALLS, gcs };
  } finally {
    await hal.cleanup();
    await emulator.stop();
  }
}

for (const key of [undefined, KEY]) {
  const { bytes, gcs } = await bytesPerCall(key);
  const label = key === undefined ? 'keyless' : 'keyed';
  console.log(
    `${label}: ${bytes.toFixed(0)} bytes allocated per call over ${CALLS} calls` +
      (gcs > 0 ? ` (${gcs} GCs ran: the figure is low; raise --max-semi-space-size)` : ''),
  );
}
