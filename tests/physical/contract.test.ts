// The HAL contract, run through PhysicalHAL against the emulated robot over both links.
import { PhysicalHAL } from '@hal/physical';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { afterAll } from 'vitest';
import { startEmulator, stopAllEmulators } from './emulator.js';
import type { Emulator } from './emulator.js';

const TIME_SCALE = 20;
const emulators = new WeakMap<HardwareAbstractionLayer, Emulator>();
afterAll(stopAllEmulators);

describeHalContract('PhysicalHAL over UDP to the emulator', {
  create: async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: 10_000,
      pty: false,
    });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-udp',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    emulators.set(hal, emulator);
    return hal;
  },
  dispose: async (hal) => emulators.get(hal)?.stop(),
  timeoutMs: 30_000,
});

describeHalContract('PhysicalHAL over a serial pseudo-terminal to the emulator', {
  create: async () => {
    const emulator = await startEmulator({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
    const hal = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-serial',
        connection: { type: 'serial', port: emulator.pty, baudRate: 115200 },
      },
      { timeScale: TIME_SCALE },
    );
    emulators.set(hal, emulator);
    return hal;
  },
  dispose: async (hal) => emulators.get(hal)?.stop(),
  timeoutMs: 30_000,
});
