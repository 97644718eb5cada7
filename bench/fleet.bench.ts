// The fleet modes over NATS: ROBOTS simulated robots in one world (real-time ticker at SPEED x),
// each served by its own gateway and driven through a NatsHAL. Two figures, each beside the naive
// alternative in the same run, interleaved round by round:
// - a 1 cm move of every robot, synchronized (issued in the same tick) vs one robot after another;
// - the fleet e-stop (every robot's e-stop issued at once, until every robot acknowledged) vs
//   e-stopping the robots one after another.
import { Fleet } from '@hal/fleet';
import type { FleetMember } from '@hal/fleet';
import { NatsHAL, openConnection, serveHalOnNats } from '@hal/nats';
import type { HalGateway } from '@hal/nats';
import { SimulationHAL, World } from '@hal/simulation';
import { startNatsServer } from '../tests/nats/nats-server.js';
import { percentile, reportFigure } from './report/figures.js';

const ROBOTS = Number(process.env['FLEET_ROBOTS'] ?? 20);
const ROUNDS = Number(process.env['FLEET_ROUNDS'] ?? 5);
const ESTOP_ROUNDS = Number(process.env['FLEET_ESTOP_ROUNDS'] ?? 20);
const SPEED = 10;

const server = await startNatsServer();
const serving = await openConnection({ servers: server.url, name: 'bench-fleet-gateways' });
const world = new World();
world.startRealtime({ speed: SPEED });
const sims: SimulationHAL[] = [];
const gateways: HalGateway[] = [];
const members: FleetMember[] = [];
for (let i = 0; i < ROBOTS; i++) {
  const id = `bench-${i}`;
  const sim = new SimulationHAL({
    world,
    clock: 'realtime',
    deviceId: id,
    start: { x: 0, y: i * 0.3, yaw: 0 },
  });
  await sim.initialize();
  sims.push(sim);
  gateways.push(
    await serveHalOnNats(sim, { connection: serving, deviceId: id, defaultDevice: false }),
  );
}
const client = await openConnection({ servers: server.url, name: 'bench-fleet-client' });
for (let i = 0; i < ROBOTS; i++) {
  const hal = new NatsHAL({ connection: client, deviceId: `bench-${i}` });
  await hal.initialize();
  members.push({ id: `bench-${i}`, hal });
}
const fleet = new Fleet(members, { estopTimeoutMs: 5000 });

async function timed(run: () => Promise<void>): Promise<number> {
  const started = performance.now();
  await run();
  return performance.now() - started;
}

function check(ok: boolean, what: string): void {
  if (!ok) throw new Error(`benchmark run failed: ${what}`);
}

const moves = { together: [] as number[], sequential: [] as number[] };
for (let round = 0; round < ROUNDS; round++) {
  const order =
    round % 2 === 0 ? (['together', 'sequential'] as const) : (['sequential', 'together'] as const);
  for (const path of order) {
    const ms = await timed(async () => {
      if (path === 'together') {
        const report = await fleet.synchronized({ kind: 'moveForward', distanceCm: 1 });
        check(report.success, `synchronized move: ${report.failed.join(', ')}`);
      } else {
        for (const m of members) check((await m.hal.locomotion.moveForward(1)).success, m.id);
      }
    });
    moves[path].push(ms);
  }
}

const estops = { together: [] as number[], sequential: [] as number[] };
for (let round = 0; round < ESTOP_ROUNDS; round++) {
  const order =
    round % 2 === 0 ? (['together', 'sequential'] as const) : (['sequential', 'together'] as const);
  for (const path of order) {
    const ms = await timed(async () => {
      if (path === 'together') {
        const report = await fleet.emergencyStop('bench');
        check(report.success, 'fleet e-stop');
      } else {
        for (const m of members) check((await m.hal.safety.emergencyStop('bench')).success, m.id);
      }
    });
    check(
      sims.every((s) => s.safety.isEmergencyStopped()),
      'every robot latched',
    );
    estops[path].push(ms);
    check((await fleet.resetEmergencyStop()).success, 'reset');
  }
}

const p50 = (xs: number[]) => percentile(xs, 50);
const fmt = (ms: number) => `${ms.toFixed(1)} ms`;
console.log(`fleet over NATS: ${ROBOTS} simulated robots (world at ${SPEED}x real time)`);
console.log(
  `1 cm move of every robot, p50 of ${ROUNDS}: synchronized ${fmt(p50(moves.together))}, one after another ${fmt(p50(moves.sequential))} (${(p50(moves.sequential) / p50(moves.together)).toFixed(1)}x)`,
);
console.log(
  `e-stop of every robot until all acknowledged, p50 of ${ESTOP_ROUNDS}: fleet e-stop ${fmt(p50(estops.together))}, one after another ${fmt(p50(estops.sequential))} (${(p50(estops.sequential) / p50(estops.together)).toFixed(1)}x)`,
);
reportFigure({
  bench: 'fleet',
  name: `synchronized 1 cm move of ${ROBOTS} robots over NATS p50`,
  value: p50(moves.together),
  unit: 'ms',
  better: 'lower',
  alternative: { name: 'one robot after another p50', value: p50(moves.sequential) },
  note: `simulated robots at ${SPEED}x real time; one move takes about ${fmt(p50(moves.sequential) / ROBOTS)}`,
});
reportFigure({
  bench: 'fleet',
  name: `fleet e-stop of ${ROBOTS} robots over NATS p50 (all acknowledged)`,
  value: p50(estops.together),
  unit: 'ms',
  better: 'lower',
  alternative: { name: 'e-stops one after another p50', value: p50(estops.sequential) },
});

for (const m of members) await m.hal.cleanup();
for (const g of gateways) await g.close();
for (const s of sims) await s.cleanup();
world.stopRealtime();
await client.close();
await serving.close();
await server.stop();
