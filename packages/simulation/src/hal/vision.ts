import { CAPABILITIES, HalError } from '@hal/types';
import type { VisionInterface } from '@hal/types';
import { renderRobotView } from '../camera.js';
import type { CameraOptions } from '../camera.js';
import { encodeJpeg, jpegDataUrl } from '../jpeg.js';
import type { JpegEncoder } from '../jpeg-encoders.js';
import { readDistanceSensors, readImu, scanAround } from '../sensors.js';
import type { HalContext } from './context.js';
import type { FrameSource } from './options.js';

/**
 * Frames from the built-in software renderer (works in Node), encoded with `encoder` (default:
 * the fastest the runtime has, see `defaultJpegEncoder`).
 */
export const softwareFrameSource =
  (options: CameraOptions, encoder?: JpegEncoder): FrameSource =>
  async (world, robot) =>
    jpegDataUrl(await encodeJpeg(renderRobotView(world, robot, options), 85, encoder));

/**
 * The simulated robot's vision: camera frames from `frameSource`, ray-cast range sensors and an
 * IMU, each present only when the robot has the feature (else NOT_IMPLEMENTED); no line sensors.
 */
export function createVision(ctx: HalContext, frameSource: FrameSource): VisionInterface {
  const lacks = (what: string, capability: string): never => {
    throw new HalError('NOT_IMPLEMENTED', `the simulated robot has no ${what}`, {
      details: { capability },
    });
  };
  const b = ctx.boundary;
  const { features, options } = ctx;
  return {
    captureFrame: () =>
      b.read('captureFrame', {}, () =>
        features.camera
          ? frameSource(ctx.world, ctx.robot())
          : lacks('camera', CAPABILITIES.camera),
      ),
    scan: (mode) =>
      b.read('scan', { mode }, (p) =>
        features.rangeSensors
          ? scanAround(ctx.world, ctx.robot(), p.mode ?? 'quick', options.rangeSensors)
          : lacks('range sensors', CAPABILITIES.rangeSensors),
      ),
    getDistanceSensors: () =>
      b.read('getDistanceSensors', {}, () =>
        features.rangeSensors
          ? readDistanceSensors(ctx.world, ctx.robot(), options.rangeSensors)
          : lacks('range sensors', CAPABILITIES.rangeSensors),
      ),
    getLineSensors: () =>
      b.read('getLineSensors', {}, () => lacks('line sensors', CAPABILITIES.lineSensors)),
    getIMU: () =>
      b.read('getIMU', {}, () => {
        if (features.imu) return readImu(ctx.robot());
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: ctx.robot().velocity().angular },
          heading: ctx.robot().reportedPose.yaw,
          source: 'odometry' as const,
        };
      }),
  };
}
