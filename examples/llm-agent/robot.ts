// Which robot the app drives: the real one when HAL_UDP_HOST or HAL_SERIAL_PORT is set, else a
// simulated one in the built-in "obstacles" arena (HAL_SIM_MAP picks another map).
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL, World } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';

export function robotFromEnv(env: NodeJS.ProcessEnv): {
  hal: HardwareAbstractionLayer;
  label: string;
} {
  const key = env['HAL_KEY'];
  const withKey = key === undefined || key === '' ? {} : { key };
  const host = env['HAL_UDP_HOST'];
  if (host !== undefined && host !== '') {
    const udpPort = Number(env['HAL_UDP_PORT'] ?? 4210);
    const hal = new PhysicalHAL({
      mode: 'physical',
      deviceId: 'cube-1',
      connection: { type: 'wifi', host, udpPort, ...withKey },
    });
    return { hal, label: `robot at udp://${host}:${udpPort}` };
  }
  const port = env['HAL_SERIAL_PORT'];
  if (port !== undefined && port !== '') {
    const hal = new PhysicalHAL({
      mode: 'physical',
      deviceId: 'cube-1',
      connection: { type: 'serial', port, baudRate: 115200, ...withKey },
    });
    return { hal, label: `robot on ${port}` };
  }
  const map = env['HAL_SIM_MAP'] ?? 'obstacles';
  const hal = new SimulationHAL({ world: new World({ map: map as 'obstacles', seed: 1 }) });
  return { hal, label: `simulator, map "${map}"` };
}
