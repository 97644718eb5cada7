// The HAL contract through a real nats-server on 127.0.0.1: NatsHAL -> NATS -> gateway -> a HAL,
// once with SimulationHAL and once with PhysicalHAL driving the emulated robot over UDP.
import { NatsHAL, serveHalOnNats } from '@hal/nats';
import type { HalGateway } from '@hal/nats';
import { PhysicalHAL } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import type { HardwareAbstractionLayer } from '@hal/types';
import { describeHalContract } from '@hal/types/testing';
import { afterAll, beforeAll } from 'vitest';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { Emulator } from '../physical/emulator.js';
import { startNatsServer, stopAllNatsServers } from './nats-server.js';
import type { NatsServer } from './nats-server.js';

const TIME_SCALE = 20;
let server: NatsServer;
let next = 0;
const owned = new WeakMap<
  HardwareAbstractionLayer,
  { gateway: HalGateway; device: HardwareAbstractionLayer; emulator?: Emulator }
>();

beforeAll(async () => {
  server = await startNatsServer();
}, 20_000);
afterAll(async () => {
  await stopAllEmulators();
  await stopAllNatsServers();
});

async function behindGateway(
  device: HardwareAbstractionLayer,
  emulator?: Emulator,
): Promise<HardwareAbstractionLayer> {
  await device.initialize();
  const deviceId = `robot-${(next += 1)}`;
  const gateway = await serveHalOnNats(device, { servers: server.url, deviceId, stateRateHz: 20 });
  const hal = new NatsHAL({ servers: server.url, deviceId });
  owned.set(hal, emulator === undefined ? { gateway, device } : { gateway, device, emulator });
  return hal;
}

async function dispose(hal: HardwareAbstractionLayer): Promise<void> {
  const parts = owned.get(hal);
  if (parts === undefined) return;
  await parts.gateway.close();
  await parts.device.cleanup();
  await parts.emulator?.stop();
}

describeHalContract('NatsHAL through nats-server to SimulationHAL', {
  create: () => behindGateway(new SimulationHAL()),
  dispose,
  timeoutMs: 30_000,
});

describeHalContract('NatsHAL through nats-server to PhysicalHAL and the emulated robot', {
  create: async () => {
    const emulator = await startEmulator({
      timeScale: TIME_SCALE,
      hostTimeoutMs: 10_000,
      pty: false,
    });
    const device = new PhysicalHAL(
      {
        mode: 'physical',
        deviceId: 'cube-nats',
        connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
      },
      { timeScale: TIME_SCALE },
    );
    return behindGateway(device, emulator);
  },
  dispose,
  timeoutMs: 30_000,
});
