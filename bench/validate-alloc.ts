// Bytes allocated and nanoseconds per call of the HAL boundary's parameter validation,
// `HalBoundary.validate('setLED' | 'drive', ...)`, against the call's zod schema run directly
// (`safeParse`, what the boundary did before it compiled its schemas with `z.compile`), interleaved in rounds in one process.
// Bytes are counted as udp-alloc.ts counts them: the young generation is made large enough that
// no GC runs while it counts, so the heap's growth over the calls is what they allocated. A tool
// beside udp-alloc.ts, not a benchmark of `pnpm bench`.
//   node --expose-gc --max-semi-space-size=256 --min-semi-space-size=256 --conditions=@hal/source --import tsx bench/validate-alloc.ts
import { PerformanceObserver } from 'node:perf_hooks';
import { HalBoundary, V1_ROBOT } from '@hal/types';
import type { CallName } from '@hal/types';

const CALLS = 20_000;
const ROUNDS = 8;
const exposedGc = (globalThis as { gc?: () => void }).gc;
if (exposedGc === undefined) throw new Error('run with --expose-gc');
const gc: () => void = exposedGc;

const boundary = new HalBoundary({
  mode: 'physical',
  config: () => V1_ROBOT,
  isEmergencyStopped: () => false,
  isReady: () => true,
});

// the arguments are made up front, as the HAL's own call site makes them, so only the
// validation is counted; `pattern` and `durationMs` are present and undefined as a HAL passes them
const POOL = 256;
const args: Record<'setLED' | 'drive', unknown[]> = {
  setLED: Array.from({ length: POOL }, (_, i) => ({ r: i, g: 255 - i, b: 7, pattern: undefined })),
  drive: Array.from({ length: POOL }, (_, i) => ({
    left: i - 128,
    right: 127 - i,
    durationMs: i % 2 === 0 ? undefined : 500 + i,
  })),
};

type Path = 'boundary' | 'zod';
let sink: unknown;

function run(call: 'setLED' | 'drive', path: Path, n: number): void {
  const inputs = args[call];
  const schema = boundary.schemas()[call];
  for (let i = 0; i < n; i++) {
    const input = inputs[i % POOL];
    if (path === 'boundary') sink = boundary.validate(call as CallName, input);
    else {
      const parsed = schema.safeParse(input);
      if (!parsed.success) throw new Error(`${call} refused ${JSON.stringify(input)}`);
      sink = parsed.data;
    }
  }
}

function measure(call: 'setLED' | 'drive', path: Path): { bytes: number; ns: number; gcs: number } {
  let gcs = 0;
  const observer = new PerformanceObserver((list) => (gcs += list.getEntries().length));
  gc();
  observer.observe({ entryTypes: ['gc'] });
  const before = process.memoryUsage().heapUsed;
  const started = process.hrtime.bigint();
  run(call, path, CALLS);
  const elapsed = Number(process.hrtime.bigint() - started);
  const after = process.memoryUsage().heapUsed;
  observer.disconnect();
  return { bytes: (after - before) / CALLS, ns: elapsed / CALLS, gcs };
}

const median = (values: number[]): number => {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)] ?? Number.NaN;
};

for (const call of ['setLED', 'drive'] as const) {
  for (const path of ['boundary', 'zod'] as const) run(call, path, 50_000); // warm up
  const figures: Record<Path, { bytes: number[]; ns: number[]; gcs: number }> = {
    boundary: { bytes: [], ns: [], gcs: 0 },
    zod: { bytes: [], ns: [], gcs: 0 },
  };
  for (let round = 0; round < ROUNDS; round++) {
    // alternate which path goes first, so neither always runs on the other's leftovers
    const order: Path[] = round % 2 === 0 ? ['boundary', 'zod'] : ['zod', 'boundary'];
    for (const path of order) {
      const { bytes, ns, gcs } = measure(call, path);
      figures[path].bytes.push(bytes);
      figures[path].ns.push(ns);
      figures[path].gcs += gcs;
    }
  }
  const b = { bytes: median(figures.boundary.bytes), ns: median(figures.boundary.ns) };
  const z = { bytes: median(figures.zod.bytes), ns: median(figures.zod.ns) };
  const gcs = figures.boundary.gcs + figures.zod.gcs;
  console.log(
    `${call}: HalBoundary.validate ${b.bytes.toFixed(0)} B/call ${b.ns.toFixed(0)} ns/call; ` +
      `zod safeParse ${z.bytes.toFixed(0)} B/call ${z.ns.toFixed(0)} ns/call; ` +
      `ratio ${(b.bytes / z.bytes).toFixed(2)}x bytes, ${(b.ns / z.ns).toFixed(2)}x time ` +
      `(medians of ${ROUNDS} interleaved rounds of ${CALLS} calls)` +
      (gcs > 0 ? ` (${gcs} GCs ran: the byte figures are low; raise --max-semi-space-size)` : ''),
  );
}
if (sink === Symbol.for('never')) console.log('unreachable');
