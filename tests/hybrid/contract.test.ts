// The HAL contract, run through HybridHAL: PhysicalHAL over UDP to the emulated robot, with a
// SimulationHAL twin.
import type { HardwareAbstractionLayer } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { afterAll } from 'vitest';
import { stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { emulatedRig } from './rig.js';

const emulators = new WeakMap<HardwareAbstractionLayer, Emulator>();
afterAll(stopAllEmulators);

describeHalContract('HybridHAL over the emulator (UDP) with a simulated twin', {
  create: async () => {
    const { hal, emulator } = await emulatedRig();
    emulators.set(hal, emulator);
    return hal;
  },
  dispose: async (hal) => emulators.get(hal)?.stop(),
  timeoutMs: 30_000,
});
