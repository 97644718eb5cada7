// The emulated camera over the real wire with the mock robot (what an installed `hal emulate`
// serves): a PhysicalHAL drives the robot over UDP and sees through the camera over HTTP.
import { parseWorldFile, realiseWorld } from '@hal/eval';
import { PhysicalHAL } from '@hal/physical';
import { afterEach, describe, expect, it } from 'vitest';
import { startEmulatedCamera } from './emulated-camera.js';
import type { EmulatedCamera } from './emulated-camera.js';
import { redRegion } from './frame-colour.fixture.js';
import { framesLater } from './served-frames.fixture.js';
import { startMockEmulator } from './mock-emulator.js';
import type { EmulateCliOptions } from './emulate-options.js';
import type { EmulatorProcess } from './emulator-process.js';

const OPTIONS: EmulateCliOptions = {
  udpPort: 0,
  bind: '127.0.0.1',
  deviceId: 'cube-camera-mock',
  insecure: false,
  timeScale: 10,
  // the camera renders and encodes in this process too: at 10x a 2 s host timeout is 200 ms of
  // real time, which a loaded machine's event loop can miss (the host timeout has its own tests)
  hostTimeoutMs: 10_000,
  pty: false,
  announce: false,
};

/** A red box 1 m ahead of the start, a little to the left. */
const WORLD = realiseWorld(
  parseWorldFile(
    JSON.stringify({
      map: 'empty',
      start: { x: 0, y: 0, yawDeg: 0 },
      objects: [{ name: 'red-box', kind: 'box', colour: 'red', x: 1, y: 0.1 }],
    }),
    'world.json',
  ),
);

const cleanups: (() => Promise<void>)[] = [];
afterEach(async () => {
  for (const cleanup of cleanups.splice(0).reverse()) await cleanup();
});

async function setUp(token?: string) {
  const emulator: EmulatorProcess = await startMockEmulator(OPTIONS);
  cleanups.push(() => emulator.stop());
  const camera: EmulatedCamera = await startEmulatedCamera({
    host: '127.0.0.1',
    port: 0,
    ...(token === undefined ? {} : { token }),
    world: WORLD,
    wheels: emulator.wheels!,
  });
  cleanups.push(() => camera.close());
  const hal = new PhysicalHAL(
    {
      mode: 'physical',
      deviceId: 'cube',
      connection: {
        type: 'wifi',
        host: '127.0.0.1',
        udpPort: emulator.ready.udp_port,
        cameraUrl: camera.url,
        ...(token === undefined ? {} : { cameraToken: token }),
      },
    },
    { timeScale: 10 },
  );
  await hal.initialize();
  cleanups.push(() => hal.cleanup());
  return { camera, hal };
}

/** A frame rendered after now (the HAL keeps the latest frame the camera sent). */
async function freshFrame(hal: PhysicalHAL, camera: EmulatedCamera): Promise<string> {
  await framesLater(camera.url, 'mock-cam');
  return hal.vision.captureFrame();
}

describe('the emulated camera with the mock robot', { timeout: 20_000 }, () => {
  it("sees the world from the robot's true pose, over UDP and MJPEG", async () => {
    const { camera, hal } = await setUp('mock-cam');
    const before = redRegion(await freshFrame(hal, camera));
    expect([before.width, before.height]).toEqual([320, 240]);
    expect(before.count).toBeGreaterThan(100);
    // the box is left of the middle (y > 0 is left), and stays left while the robot drives at it
    expect(before.column).toBeLessThan(160);

    const moved = await hal.locomotion.moveForward(40);
    expect(moved.success, moved.error).toBe(true);
    expect(camera.pose().x).toBeCloseTo(0.4, 2);
    const after = redRegion(await freshFrame(hal, camera));
    expect(after.count).toBeGreaterThan(before.count * 1.5);
    expect(after.column).toBeLessThan(before.column);
  });
});
