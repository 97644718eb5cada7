// The V1 cube with its camera, emulated over the real wire: `hal emulate --camera --world FILE` as
// a process runs the firmware's cube-emulator (UDP) and serves the ESP32-CAM's interface (MJPEG)
// with frames rendered from the emulated body's true pose in the world file. One harness for the
// tests that drive it with a PhysicalHAL or point `hal` at it.
import { mkdtemp, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PhysicalHAL } from '@hal/physical';
import { EMULATOR_PATH, requireEmulator } from '../physical/emulator.js';
import { startHalProcess, stopAllHal } from './hal-process.js';

type Line = Record<string, unknown> & { event: string };

/** What {@link startEmulatedCube} starts with. */
export interface EmulatedCubeOptions {
  /** The world, in the eval task format (`{ map, start, objects }`): written to a file. */
  world: unknown;
  /** The robot's clock speed-up (`--time-scale`). Default 1. */
  timeScale?: number;
  /** The camera's token (`--camera-token`). Default none. */
  token?: string;
  /**
   * The robot's host timeout in its own milliseconds (`--host-timeout-ms`). Default the longest,
   * 10 s: at 10x the firmware's 2 s is 200 ms of real time, which a loaded machine rendering the
   * camera in the same process can miss; these tests are not tests of the timeout.
   */
  hostTimeoutMs?: number;
}

/** A running emulated cube with its camera. */
export interface EmulatedCube {
  /** Its UDP port on 127.0.0.1. */
  udpPort: number;
  /** The camera's base URL, as `hal emulate` printed it. */
  cameraUrl: string;
  /**
   * A PhysicalHAL for it over UDP with its camera, not yet initialised. With `freshCaptures`,
   * each `captureFrame` first waits for two frames rendered after it was called: at a time scale
   * above 1 the robot's clock outruns the camera's real-time frames (at 10x, the frame in flight
   * is a second of the robot's motion), which a camera beside a robot at 1x never meets.
   */
  physicalHal(options?: { freshCaptures?: boolean }): PhysicalHAL;
  /**
   * Waits (at most 5 s) until the camera has sent `frames` more frames: each is rendered as it is
   * sent, so afterwards the latest shows the robot where it is now.
   */
  freshFrames(frames?: number): Promise<void>;
  /** Stops every `hal` process of the test and removes the world file. */
  dispose(): Promise<void>;
}

/** Starts `hal emulate --camera 0 --world FILE` and waits until it is ready. */
export async function startEmulatedCube(options: EmulatedCubeOptions): Promise<EmulatedCube> {
  requireEmulator();
  const timeScale = options.timeScale ?? 1;
  const dir = await mkdtemp(join(tmpdir(), 'hal-emulated-cube-'));
  const file = join(dir, 'world.json');
  await writeFile(file, JSON.stringify(options.world));
  const emulate = startHalProcess<Line>([
    '--json',
    'emulate',
    '--emulator',
    EMULATOR_PATH,
    '--udp-port',
    '0',
    '--no-pty',
    '--no-announce',
    '--time-scale',
    String(timeScale),
    '--host-timeout-ms',
    String(options.hostTimeoutMs ?? 10_000),
    '--camera',
    '0',
    ...(options.token === undefined ? [] : ['--camera-token', options.token]),
    '--world',
    file,
  ]);
  const ready = await emulate.waitFor((l) => l.event === 'ready');
  const udpPort = ready['udpPort'] as number;
  const cameraUrl = (ready['camera'] as { url: string }).url;
  const auth = options.token === undefined ? '' : `?token=${options.token}`;
  const served = async (): Promise<number> =>
    ((await (await fetch(`${cameraUrl}/status${auth}`)).json()) as { frames_served: number })
      .frames_served;
  const fresh = async (frames: number): Promise<void> => {
    const target = (await served()) + frames;
    const deadline = Date.now() + 5000;
    while ((await served()) < target) {
      if (Date.now() > deadline) throw new Error('the camera sent no new frames in 5 s');
      await new Promise((resolve) => setTimeout(resolve, 30));
    }
  };
  return {
    udpPort,
    cameraUrl,
    physicalHal: (halOptions = {}) => {
      const hal = new PhysicalHAL(
        {
          mode: 'physical',
          deviceId: 'cube',
          connection: {
            type: 'wifi',
            host: '127.0.0.1',
            udpPort,
            cameraUrl,
            ...(options.token === undefined ? {} : { cameraToken: options.token }),
          },
        },
        { timeScale },
      );
      if (halOptions.freshCaptures === true) {
        const capture = hal.vision.captureFrame.bind(hal.vision);
        hal.vision.captureFrame = async () => {
          await fresh(2);
          return await capture();
        };
      }
      return hal;
    },
    freshFrames: (frames = 3) => fresh(frames),
    dispose: async () => {
      await stopAllHal();
      await rm(dir, { recursive: true, force: true });
    },
  };
}
