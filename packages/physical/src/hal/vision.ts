import { CAPABILITIES, HalError } from '@hal/types';
import type { IMUReading, VisionInterface } from '@hal/types';
import type { MjpegCamera } from '../camera/mjpeg.js';
import type { HalContext } from './context.js';

/**
 * What the V1 robot senses: camera frames from the ESP32-CAM when one is configured, and an IMU
 * reading made from odometry. It has no range or line sensors: those calls reject NOT_IMPLEMENTED.
 */
export function createVision(ctx: HalContext, camera: MjpegCamera | undefined): VisionInterface {
  const lacks = (what: string, capability: string): never => {
    throw new HalError('NOT_IMPLEMENTED', `the V1 stepper cube has no ${what}`, {
      details: { capability },
    });
  };
  const b = ctx.boundary;
  return {
    captureFrame: () =>
      b.read('captureFrame', {}, async () => {
        if (camera === undefined) {
          throw new HalError(
            'NOT_IMPLEMENTED',
            'no camera configured: set connection.cameraUrl to the ESP32-CAM address',
            { details: { capability: CAPABILITIES.camera } },
          );
        }
        return await camera.captureFrame();
      }),
    scan: (mode) =>
      b.read('scan', { mode }, () => lacks('range sensors', CAPABILITIES.rangeSensors)),
    getDistanceSensors: () =>
      b.read('getDistanceSensors', {}, () => lacks('range sensors', CAPABILITIES.rangeSensors)),
    getLineSensors: () =>
      b.read('getLineSensors', {}, () => lacks('line sensors', CAPABILITIES.lineSensors)),
    getIMU: () =>
      b.read('getIMU', {}, (): IMUReading => {
        const pose = ctx.tracker.pose();
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: pose.velocity.angular },
          heading: pose.rotation.yaw,
          source: 'odometry',
        };
      }),
  };
}
