// The checkout's `hal` (scripts/hal.js and the bundle it runs, as `pnpm hal` starts it) against
// the firmware emulator over UDP, its serial pty, WebSocket and NATS. The bundle keeps native
// packages (serialport's bindings) outside and loads them at run time: a way of loading them that
// the bundle's CommonJS refuses shows here, and nowhere a test runs the CLI from source.
import { afterAll, beforeAll, describe, it } from 'vitest';
import { HAL_LAUNCHER } from '../helpers/hal-process.js';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import { startNatsServer, stopAllNatsServers } from '../nats/nats-server.js';
import { TRANSPORTS, expectFromRobot, statusOver } from './every-transport.js';
import type { TransportRig } from './every-transport.js';

const DEVICE_ID = 'cube-launcher';
let rig: TransportRig;

beforeAll(async () => {
  const [emulator, nats] = await Promise.all([
    startEmulator({ deviceId: DEVICE_ID }),
    startNatsServer(),
  ]);
  rig = { emulator, nats };
});
afterAll(async () => {
  await Promise.all([stopAllEmulators(), stopAllNatsServers()]);
});

describe('the checkout launcher (scripts/hal.js) on the emulated robot', () => {
  it.each(TRANSPORTS)("answers hal status over %s with the robot's own identity", async (way) => {
    expectFromRobot(await statusOver(way, HAL_LAUNCHER, rig), DEVICE_ID);
  });
});
