// `hal emulate --camera`: the ESP32-CAM of the emulated robot. Its frames are rendered by the
// simulator's camera from where the emulated body truly is (its wheel steps integrated from the
// world's start), in the world of a file or an empty arena, and served as the camera serves them.
import { BUILTIN_MAPS } from '@hal/simulation';
import type { RealisedWorld } from '@hal/eval';
import { BodyPose } from './body-pose.js';
import type { WheelPositions } from './body-pose.js';
import { cameraFrames } from './camera-frames.js';
import { startCameraServer } from './camera-server.js';
import type { CameraServer } from './camera-server.js';

/** Options of {@link startEmulatedCamera}. */
export interface EmulatedCameraOptions {
  host: string;
  port: number;
  token?: string;
  /** The world it looks at; default the empty arena, from its start. */
  world?: RealisedWorld;
  /** The emulated robot's wheel positions now, steps from boot. */
  wheels: () => WheelPositions;
}

/** A served emulated camera. */
export interface EmulatedCamera {
  readonly server: CameraServer;
  /** The camera's base URL, as a PhysicalHAL's `connection.cameraUrl` takes it. */
  readonly url: string;
  /** The body's true pose now, metres and radians. */
  pose(): { x: number; y: number; yaw: number };
  close(): Promise<void>;
}

/** The host part of a URL that reaches `bind` from this machine (every interface: loopback). */
function reachable(bind: string): string {
  return bind === '0.0.0.0' ? '127.0.0.1' : bind;
}

/**
 * Starts the camera. The body stands at the world's start with the wheel positions it has now;
 * each frame first brings it up to the wheels' latest positions.
 */
export async function startEmulatedCamera(options: EmulatedCameraOptions): Promise<EmulatedCamera> {
  const start = options.world?.start ?? BUILTIN_MAPS.empty.starts[0] ?? { x: 0, y: 0, yaw: 0 };
  const body = new BodyPose(start, undefined, options.wheels());
  const pose = () => {
    body.update(options.wheels());
    return body.pose;
  };
  const frames = cameraFrames(pose, options.world?.map);
  const server = await startCameraServer({
    host: options.host,
    port: options.port,
    ...(options.token === undefined ? {} : { token: options.token }),
    frame: () => frames.frame(),
  });
  return {
    server,
    url: `http://${reachable(options.host)}:${server.port}`,
    pose,
    close: () => server.close(),
  };
}
