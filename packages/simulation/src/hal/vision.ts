import { CAPABILITIES, HalError } from '@hal/types';
import type { VisionInterface } from '@hal/types';
import { renderRobotView } from '../camera.js';
import type { CameraOptions } from '../camera.js';
import { encodeJpeg, jpegDataUrl } from '../jpeg.js';
import type { JpegEncoder } from '../jpeg-encoders.js';
import { SimulatedImu } from '../gyro.js';
import type { SimRobot } from '../robot/sim-robot.js';
import { readDistanceSensors, scanAround } from '../sensors.js';
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
 * The simulated robot's vision: camera frames from `frameSource`, ray-cast range sensors (`scan`
 * reports what they see, in the robot's believed frame) and an IMU (a drifting gyro's heading),
 * each present only when the robot has the feature (else NOT_IMPLEMENTED, and without an IMU the
 * odometry's heading); no line sensors.
 */
export function createVision(ctx: HalContext, frameSource: FrameSource): VisionInterface {
  const lacks = (what: string, capability: string): never => {
    throw new HalError('NOT_IMPLEMENTED', `the simulated robot has no ${what}`, {
      details: { capability },
    });
  };
  const b = ctx.boundary;
  const { features, options } = ctx;
  // One IMU per robot, powered on with the HAL (or, for a robot a map change re-created, at its
  // first read); its errors are seeded from the world's random source when first read.
  const imus = new WeakMap<SimRobot, SimulatedImu>();
  const imuOf = (robot: SimRobot): SimulatedImu => {
    let imu = imus.get(robot);
    if (imu === undefined) {
      imu = new SimulatedImu(robot, options.imu ?? {}, () =>
        Math.floor(ctx.world.random.next() * 0x100000000),
      );
      imus.set(robot, imu);
    }
    return imu;
  };
  if (features.imu) imuOf(ctx.robot());
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
        if (features.imu) return imuOf(ctx.robot()).read(ctx.robot());
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: ctx.robot().velocity().angular },
          heading: ctx.robot().reportedPose.yaw,
          source: 'odometry' as const,
        };
      }),
  };
}
