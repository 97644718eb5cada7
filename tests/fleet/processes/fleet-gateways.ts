// A robot host serving many robots: COUNT SimulationHALs in one world (real-time ticker at
// SPEED x), each on NATS at SERVER through its own gateway, all sharing one connection, as
// `${PREFIX}00`, `${PREFIX}01`, ... on the grid (or in the column) of ../layout.ts. Prints {"event":"serving"} once
// every gateway serves. Killed with SIGKILL by the tests, as a crashed robot host would be.
import { openConnection, serveHalOnNats } from '@hal/nats';
import { SimulationHAL, World } from '@hal/simulation';
import { columnStart, deviceId, gridStart } from '../layout.js';

const [
  servers = '',
  prefix = 'r',
  countText = '1',
  speedText = '1',
  stateText = '10',
  layout = 'grid',
] = process.argv.slice(2);
const count = Number(countText);
const speed = Number(speedText);
const world = new World();
world.startRealtime({ speed });
const connection = await openConnection({ servers, name: `fleet-gateways-${prefix}` });
const devices: string[] = [];
for (let i = 0; i < count; i++) {
  const id = deviceId(prefix, i);
  const hal = new SimulationHAL({
    world,
    clock: 'realtime',
    deviceId: id,
    start: layout === 'column' ? columnStart(i) : gridStart(i),
  });
  await hal.initialize();
  await serveHalOnNats(hal, {
    connection,
    deviceId: id,
    defaultDevice: false,
    stateRateHz: Number(stateText),
  });
  devices.push(id);
}
process.stdout.write(`${JSON.stringify({ event: 'serving', devices })}\n`);
