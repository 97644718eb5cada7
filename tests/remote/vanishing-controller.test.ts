// A controlling client that vanishes, against the real robot stack: serveHal -> PhysicalHAL ->
// UDP -> the emulated robot. The robot's own events say when its motors stopped and why.
import { PhysicalHAL } from '@hal/physical';
import { encodeArgs, encodeMessage } from '@hal/remote';
import { serveHal } from '@hal/remote/server';
import type { HalServer } from '@hal/remote/server';
import { afterAll, afterEach, describe, expect, it } from 'vitest';
import { WebSocket } from 'ws';
import { startEmulator, stopAllEmulators } from '../physical/emulator.js';
import type { EmulatorEvent } from '../physical/emulator.js';

const HEARTBEAT_TIMEOUT_MS = 500;
let server: HalServer | undefined;
let physical: PhysicalHAL | undefined;

afterEach(async () => {
  await server?.close();
  await physical?.cleanup();
});
afterAll(stopAllEmulators);

/** Serves PhysicalHAL on an emulator (real time, host timeout 10 s so only the server stops it). */
async function rig() {
  const emulator = await startEmulator({ hostTimeoutMs: 10_000, pty: false });
  physical = new PhysicalHAL({
    mode: 'physical',
    deviceId: 'cube-vanish',
    connection: { type: 'wifi', host: '127.0.0.1', udpPort: emulator.udpPort },
  });
  await physical.initialize();
  server = await serveHal(physical, { port: 0, heartbeatTimeoutMs: HEARTBEAT_TIMEOUT_MS });
  const socket = new WebSocket(server.url);
  await new Promise((resolve, reject) => {
    socket.once('message', resolve); // the hello
    socket.once('error', reject);
  });
  // An endless drive: only a stop ends it.
  socket.send(
    encodeMessage(
      'hal.remote.call',
      { deviceId: 'vanishing' },
      { id: '1', call: 'drive', args: encodeArgs([200, 200]) },
    ),
  );
  const started = await emulator.waitFor((e) => e.event === 'move_started', 5000);
  return { emulator, socket, started };
}

const finished = (e: EmulatorEvent) => e.event === 'move_finished';

describe('a controller that vanishes, against the emulated robot', () => {
  it('has the robot stopped when its socket is destroyed mid-drive', async () => {
    const { emulator, socket } = await rig();
    const cut = Date.now();
    socket.terminate();
    const done = await emulator.waitFor(finished, 3000);
    expect(Date.now() - cut).toBeLessThan(2000);
    expect(done['outcome']).not.toBe('completed');
  });

  it('has the robot stopped within the heartbeat timeout when it goes silent', async () => {
    const { emulator, socket, started } = await rig();
    const done = await emulator.waitFor(finished, 5000);
    const ranMs = Number(done['t_ms']) - Number(started['t_ms']);
    // On the robot's clock: stopped after the heartbeat timeout, well before the host timeout.
    expect(ranMs).toBeGreaterThanOrEqual(HEARTBEAT_TIMEOUT_MS - 50);
    expect(ranMs).toBeLessThan(HEARTBEAT_TIMEOUT_MS + 1500);
    expect(done['outcome']).not.toBe('completed');
    await new Promise<void>((resolve) => {
      if (socket.readyState === WebSocket.CLOSED) resolve();
      else socket.once('close', () => resolve());
    });
  });
});
