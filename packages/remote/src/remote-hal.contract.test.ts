// The HAL contract, run through real WebSocket sockets on 127.0.0.1:
// RemoteHAL -> serveHal -> SimulationHAL.
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { RemoteHAL } from './index.js';
import { serveHal } from './server/index.js';
import type { HalServer } from './server/index.js';

const served = new WeakMap<HardwareAbstractionLayer, { server: HalServer; sim: SimulationHAL }>();

describeHalContract('RemoteHAL over WebSocket to a SimulationHAL', {
  create: async () => {
    const sim = new SimulationHAL();
    await sim.initialize();
    const server = await serveHal(sim, { port: 0 });
    const hal = new RemoteHAL({ url: server.url });
    served.set(hal, { server, sim });
    return hal;
  },
  dispose: async (hal) => {
    const rig = served.get(hal);
    await rig?.server.close();
    await rig?.sim.cleanup();
  },
});
