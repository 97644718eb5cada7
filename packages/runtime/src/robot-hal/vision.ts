import type { HalBoundary, IMUReading, RobotPort, VisionInterface } from '@hal/types';

/**
 * What the robot senses, each from the port when it has the part (else NOT_IMPLEMENTED in its
 * world's words). Without a measured IMU, `getIMU` is made from odometry: the heading and turn
 * rate of the pose, no acceleration, `source: 'odometry'`.
 */
export function createVision(b: HalBoundary, port: RobotPort): VisionInterface {
  return {
    captureFrame: () =>
      b.read('captureFrame', {}, () => {
        if (port.captureFrame === undefined) throw port.lacks('camera');
        return port.captureFrame();
      }),
    scan: (mode) =>
      b.read('scan', { mode }, (p) => {
        if (port.scan === undefined) throw port.lacks('range sensors');
        return port.scan(p.mode ?? 'quick');
      }),
    getDistanceSensors: () =>
      b.read('getDistanceSensors', {}, () => {
        if (port.distanceSensors === undefined) throw port.lacks('range sensors');
        return port.distanceSensors();
      }),
    getLineSensors: () =>
      b.read('getLineSensors', {}, (): number[] => {
        throw port.lacks('line sensors');
      }),
    getIMU: () =>
      b.read('getIMU', {}, (): IMUReading => {
        if (port.imu !== undefined) return port.imu();
        const pose = port.pose();
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: pose.velocity.angular },
          heading: pose.rotation.yaw,
          source: 'odometry',
        };
      }),
  };
}
