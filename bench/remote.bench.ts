// The cost of the WebSocket hop: one call through RemoteHAL (client, socket on 127.0.0.1, server,
// envelope and zod checks both ways) beside the same call made directly on the same HAL, the two
// interleaved in one run. Prints p50/p99 and the ratio, and reports them as figures.
import { RemoteHAL } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { percentile, reportFigure } from './report/figures.js';

const ROUNDS = 2000;
const WARMUP = 200;

const fmt = (ms: number) => `${(ms * 1000).toFixed(0)} us`;

type Call = (hal: HardwareAbstractionLayer, i: number) => Promise<unknown>;

const CALLS: Array<[string, Call]> = [
  [
    'setLED',
    async (hal, i) => {
      const result = await hal.communication.setLED(i % 256, 0, 0);
      if (!result.success) throw new Error(`setLED failed: ${result.error}`);
    },
  ],
  ['getPose', (hal) => hal.locomotion.getPose()],
];

const sim = new SimulationHAL();
await sim.initialize();
const server = await serveHal(sim, { port: 0 });
const remote = new RemoteHAL({ url: server.url });
await remote.initialize();

for (const [name, call] of CALLS) {
  const direct: number[] = [];
  const viaRemote: number[] = [];
  for (let i = 0; i < WARMUP + ROUNDS; i++) {
    // Interleaved, alternating which goes first, so load on the machine hits both alike.
    const order: Array<[HardwareAbstractionLayer, number[]]> =
      i % 2 === 0
        ? [
            [sim, direct],
            [remote, viaRemote],
          ]
        : [
            [remote, viaRemote],
            [sim, direct],
          ];
    for (const [hal, samples] of order) {
      const start = performance.now();
      await call(hal, i);
      if (i >= WARMUP) samples.push(performance.now() - start);
    }
  }
  const d50 = percentile(direct, 50);
  const d99 = percentile(direct, 99);
  const r50 = percentile(viaRemote, 50);
  const r99 = percentile(viaRemote, 99);
  console.log(
    `${name}: RemoteHAL p50 ${fmt(r50)} p99 ${fmt(r99)} | direct p50 ${fmt(d50)} p99 ${fmt(d99)} | ` +
      `ratio p50 ${(r50 / d50).toFixed(1)}x, p99 ${(r99 / d99).toFixed(1)}x (${ROUNDS} calls each)`,
  );
  for (const [stat, value, base] of [
    ['p50', r50, d50],
    ['p99', r99, d99],
  ] as const) {
    reportFigure({
      bench: 'remote',
      name: `${name} through RemoteHAL ${stat}`,
      value: value * 1000,
      unit: 'us',
      better: 'lower',
      alternative: { name: `${name} direct ${stat}`, value: base * 1000 },
    });
  }
}

await remote.cleanup();
await server.close();
await sim.cleanup();
