// The HAL contract through every layer, over real sockets: RemoteHAL -WebSocket-> serveHal ->
// PhysicalHAL -UDP-> the firmware's emulated robot.
import { PhysicalHAL } from '@hal/physical';
import { RemoteHAL } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { afterAll } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';

const TIME_SCALE = 20;
const rigs = new WeakMap<
  HardwareAbstractionLayer,
  { emulator: Emulator; physical: PhysicalHAL; server: HalServer }
>();
afterAll(stopAllEmulators);

describeHalContract('RemoteHAL over WebSocket to PhysicalHAL and the emulated robot (UDP)', {
  create: async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: 10_000,
      pty: false,
    });
    const physical = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-remote',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    await physical.initialize();
    const server = await serveHal(physical, { port: 0 });
    const hal = new RemoteHAL({ url: server.url });
    rigs.set(hal, { emulator, physical, server });
    return hal;
  },
  dispose: async (hal) => {
    const rig = rigs.get(hal);
    await rig?.server.close();
    await rig?.physical.cleanup();
    await rig?.emulator.stop();
  },
  timeoutMs: 30_000,
});
