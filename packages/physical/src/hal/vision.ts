import { HalError } from '@hal/types';
import type { IMUReading, VisionInterface } from '@hal/types';
import type { MjpegCamera } from '../camera/mjpeg.js';
import type { HalContext } from './context.js';

/**
 * What the V1 robot senses: camera frames from the ESP32-CAM when one is configured, and an IMU
 * reading made from odometry. It has no range or line sensors: those calls reject NOT_IMPLEMENTED.
 */
export function createVision(ctx: HalContext, camera: MjpegCamera | undefined): VisionInterface {
  const lacks = (what: string) =>
    Promise.reject(
      new HalError('NOT_IMPLEMENTED', `the V1 stepper cube has no ${what}`, {
        details: { capability: what },
      }),
    );
  return {
    captureFrame: async () => {
      if (camera === undefined) {
        throw new HalError(
          'NOT_IMPLEMENTED',
          'no camera configured: set connection.cameraUrl to the ESP32-CAM address',
        );
      }
      return await camera.captureFrame();
    },
    scan: () => lacks('range sensors'),
    getDistanceSensors: () => lacks('range sensors'),
    getLineSensors: () => lacks('line sensors'),
    getIMU: async (): Promise<IMUReading> => {
      const pose = ctx.tracker.pose();
      return {
        acceleration: { x: 0, y: 0, z: 0 },
        gyroscope: { x: 0, y: 0, z: pose.velocity.angular },
        heading: pose.rotation.yaw,
        source: 'odometry',
      };
    },
  };
}
