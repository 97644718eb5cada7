// A HybridHAL over PhysicalHAL (UDP to the emulated robot) and a SimulationHAL twin.
import { HybridHAL } from '@hal/hybrid';
import type { HybridHALOptions } from '@hal/hybrid';
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import type { SimulationHALOptions } from '@hal/simulation';
import { startEmulator } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';

/** The emulator's clock runs this much faster than real time. */
export const TIME_SCALE = 20;

export interface EmulatedRig {
  hal: HybridHAL;
  physical: PhysicalHAL;
  twin: SimulationHAL;
  emulator: Emulator;
}

/** Starts an emulator and builds a hybrid HAL over it (not yet initialised). */
export async function emulatedRig(
  options: { twin?: SimulationHALOptions; hybrid?: Partial<HybridHALOptions> } = {},
): Promise<EmulatedRig> {
  const emulator = await startEmulator({
    timeScale: TIME_SCALE,
    hostTimeoutMs: 10_000,
    pty: false,
  });
  const physical = new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: 'cube-hybrid',
      connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
    },
    { timeScale: TIME_SCALE },
  );
  const twin = new SimulationHAL({ deviceId: 'cube-hybrid-twin', ...options.twin });
  const hal = new HybridHAL({ physical, twin, ...options.hybrid });
  return { hal, physical, twin, emulator };
}
