// A gateway process: serves a SimulationHAL (real-time clock, so a move takes as long as on the
// robot) on NATS at SERVER as DEVICE, and prints {"event":"serving"} once it is. Killed with
// SIGKILL by the tests, as a crashed or unplugged robot host would be.
import { serveHalOnNats } from '@hal/nats';
import { SimulationHAL } from '@hal/simulation';

const [servers = '', deviceId = 'sim-1'] = process.argv.slice(2);
const hal = new SimulationHAL({ clock: 'realtime' });
await hal.initialize();
await serveHalOnNats(hal, { servers, deviceId, stateRateHz: 20 });
process.stdout.write(`${JSON.stringify({ event: 'serving', deviceId })}\n`);
