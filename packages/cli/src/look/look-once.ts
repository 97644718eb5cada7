// One look through a HAL for `hal look`: the robot's camera model (the one its HAL reports, else
// V1's), the pose, one frame decoded once, and what perception makes of it. The decoded image is
// kept for `--save`.
import { decodeFrame, Perception } from '@hal/perception';
import type { Percept, RgbaImage } from '@hal/perception';
import {
  CameraModelSchema,
  CAPABILITIES,
  HalError,
  hasCapability,
  V1_CAMERA,
  withTimeout,
} from '@hal/types';
import type { CameraModel, HardwareAbstractionLayer } from '@hal/types';

/** What one look saw, with the frame it saw it in. */
export interface LookResult {
  percept: Percept;
  image: RgbaImage;
  perception: Perception;
}

/**
 * The camera model the HAL reports for its robot (`getDeviceInfo().camera`: the simulator's, a
 * calibrated cube's, a served robot's), else V1's (a HAL that predates the field).
 */
export function cameraOfHal(hal: HardwareAbstractionLayer): CameraModel {
  const parsed = CameraModelSchema.safeParse(hal.getDeviceInfo().camera);
  return parsed.success ? parsed.data : { ...V1_CAMERA };
}

/**
 * Throws NOT_IMPLEMENTED naming the robot (`who`) when its HAL offers no camera, with `hint`
 * saying how to give it one.
 */
export function requireCamera(hal: HardwareAbstractionLayer, who: string, hint: string): void {
  const { capabilities } = hal.getDeviceInfo();
  if (hasCapability(capabilities, CAPABILITIES.camera)) return;
  throw new HalError('NOT_IMPLEMENTED', `the ${who} has no camera: it cannot look${hint}`, {
    details: { capability: CAPABILITIES.camera },
  });
}

/** Looks once through `hal` with `camera`; every wait bounded by `timeoutMs`. */
export async function lookOnce(
  hal: HardwareAbstractionLayer,
  camera: CameraModel,
  timeoutMs: number,
): Promise<LookResult> {
  const perception = new Perception(hal, { camera, timeoutMs });
  const pose = await perception.pose();
  const capturedAt = Date.now();
  const frame = await withTimeout(hal.vision.captureFrame(), timeoutMs);
  if (frame === undefined) {
    throw new HalError('TIMEOUT', `the camera gave no frame within ${timeoutMs} ms`);
  }
  const image = await decodeFrame(frame.value);
  if (image.width !== camera.width || image.height !== camera.height) {
    throw new HalError(
      'INVALID_PARAMETER',
      `the camera sends ${image.width}x${image.height} frames but its model says ${camera.width}x${camera.height}: calibrate the camera (or set its resolution to the model's)`,
      { details: { width: image.width, height: image.height } },
    );
  }
  const percept = await perception.perceiver.perceiveImage(image, pose, frame.value, capturedAt);
  return { percept, image, perception };
}
