// The cost of NATS between a controller and a robot: a command's request/reply latency (p50/p99)
// through NatsHAL -> nats-server -> gateway -> HAL, against calling the same HAL directly,
// interleaved round by round, for a simulated robot and for PhysicalHAL driving the emulated
// robot over UDP; then how many simulated robots one gateway process serves at 20 Hz state.
// Starts its own nats-server (Debian's, installed by scripts/setup.sh) on 127.0.0.1.
import { NatsHAL, openConnection, serveHalOnNats } from '@hal/nats';
import type { HalGateway } from '@hal/nats';
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { delay } from '@hal/types';
import { startEmulator } from '../tests/physical/emulator.js';
import { startNatsServer } from '../tests/nats/nats-server.js';
import { percentile, reportFigure } from './report/figures.js';

const ROUNDS = 1000;
const WARMUP = 100;
const STATE_HZ = 20;

const us = (ms: number) => `${(ms * 1000).toFixed(0)} us`;

/** setLED round trips, a direct call and a NATS call alternating, so both see the same load. */
async function interleaved(
  label: string,
  direct: HardwareAbstractionLayer,
  remote: HardwareAbstractionLayer,
) {
  const times = { direct: [] as number[], nats: [] as number[] };
  for (let i = 0; i < WARMUP + ROUNDS; i++) {
    for (const [path, hal] of [
      ['direct', direct],
      ['nats', remote],
    ] as const) {
      const start = performance.now();
      const result = await hal.communication.setLED(i % 256, 0, 0, 'solid');
      const elapsed = performance.now() - start;
      if (!result.success) throw new Error(`${label} ${path} setLED failed: ${result.error}`);
      if (i >= WARMUP) times[path].push(elapsed);
    }
  }
  for (const p of [50, 99]) {
    const d = percentile(times.direct, p);
    const n = percentile(times.nats, p);
    console.log(`${label}: p${p} direct ${us(d)}, through NATS ${us(n)} (${(n / d).toFixed(1)}x)`);
    reportFigure({
      bench: 'nats',
      name: `${label} command p${p} through NATS`,
      value: n * 1000,
      unit: 'us',
      better: 'lower',
      alternative: { name: 'direct call', value: d * 1000 },
    });
  }
}

async function latency(url: string): Promise<void> {
  const sim = new SimulationHAL();
  await sim.initialize();
  const simGateway = await serveHalOnNats(sim, {
    servers: url,
    deviceId: 'bench-sim',
    stateRateHz: STATE_HZ,
  });
  const simRemote = new NatsHAL({ servers: url, deviceId: 'bench-sim' });
  await simRemote.initialize();
  await interleaved('simulated robot', sim, simRemote);
  await simRemote.cleanup();
  await simGateway.close();
  await sim.cleanup();

  const emulator = await startEmulator({ hostTimeoutMs: 10_000, pty: false });
  const robot = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'bench-cube',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
  });
  await robot.initialize();
  const robotGateway = await serveHalOnNats(robot, {
    servers: url,
    deviceId: 'bench-cube',
    stateRateHz: STATE_HZ,
  });
  const robotRemote = new NatsHAL({ servers: url, deviceId: 'bench-cube' });
  await robotRemote.initialize();
  await interleaved('emulated robot', robot, robotRemote);
  await robotRemote.cleanup();
  await robotGateway.close();
  await robot.cleanup();
  await emulator.stop();
}

/** Serves `count` simulated robots from this process and measures the state rate a subscriber sees. */
async function stateRate(url: string, count: number): Promise<number> {
  const nc = await openConnection({ servers: url });
  const robots: Array<{ hal: SimulationHAL; gateway: HalGateway }> = [];
  for (let i = 0; i < count; i++) {
    const hal = new SimulationHAL();
    await hal.initialize();
    const gateway = await serveHalOnNats(hal, {
      connection: nc,
      deviceId: `fleet-${i}`,
      defaultDevice: false,
      stateRateHz: STATE_HZ,
    });
    robots.push({ hal, gateway });
  }
  const watcher = await openConnection({ servers: url });
  await delay(500);
  let received = 0;
  const sub = watcher.subscribe('hal.v1.dev.*.motor.differential.state', {
    callback: () => {
      received += 1;
    },
  });
  const seconds = 2;
  await delay(seconds * 1000);
  sub.unsubscribe();
  for (const { hal, gateway } of robots) {
    await gateway.close();
    await hal.cleanup();
  }
  await watcher.close();
  await nc.close();
  return received / seconds / count;
}

async function capacity(url: string): Promise<void> {
  const ladder = [10, 25, 50, 100, 200, 400, 800];
  let served = 0;
  let dropped = false;
  for (const count of ladder) {
    const hz = await stateRate(url, count);
    console.log(`${count} simulated robots in one gateway process: ${hz.toFixed(1)} Hz state each`);
    if (hz < STATE_HZ * 0.95) {
      dropped = true;
      break;
    }
    served = count;
  }
  const bound = dropped ? '' : ' (the largest count tried: at least that many)';
  console.log(
    `one gateway process serves ${served} simulated robots at ${STATE_HZ} Hz state${bound}`,
  );
  reportFigure({
    bench: 'nats',
    name: `simulated robots served at ${STATE_HZ} Hz state by one gateway process`,
    value: served,
    unit: 'robots',
    better: 'higher',
  });
}

const server = await startNatsServer();
try {
  await latency(server.url);
  await capacity(server.url);
} finally {
  await server.stop();
}
process.exit(0);
