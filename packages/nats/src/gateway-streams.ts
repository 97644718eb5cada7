import { CAPABILITIES, hasCapability } from '@hal/types';
import type { HardwareAbstractionLayer, RobotConfig } from '@hal/types';
import { wheelVelocities } from './drive-mapping.js';
import type { DifferentialState, ImuData, RangeData } from './messages.js';

/** The state stream's payload, read from the HAL. */
export async function readDifferentialState(
  hal: HardwareAbstractionLayer,
  robot: RobotConfig,
): Promise<DifferentialState> {
  const pose = await hal.locomotion.getPose();
  return {
    ...wheelVelocities(pose.velocity.linear, pose.velocity.angular, robot),
    linear_vel_m_per_s: pose.velocity.linear,
    angular_vel_rad_per_s: pose.velocity.angular,
    x_m: pose.position.x,
    y_m: pose.position.y,
    yaw_rad: pose.rotation.yaw,
    emergency_stopped: hal.safety.isEmergencyStopped(),
    timestamp_ms: Date.now(),
  };
}

/** The IMU stream's payload, or undefined when the device offers no IMU (nothing is streamed). */
export async function readImu(hal: HardwareAbstractionLayer): Promise<ImuData | undefined> {
  if (!hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.imu)) return undefined;
  const imu = await hal.vision.getIMU();
  return {
    accel_m_per_s2: imu.acceleration,
    gyro_rad_per_s: imu.gyroscope,
    heading_rad: imu.heading,
    source: imu.source ?? 'sensor',
  };
}

/** The range stream's payload, or undefined when the device offers no range sensors. */
export async function readRange(hal: HardwareAbstractionLayer): Promise<RangeData | undefined> {
  if (!hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.rangeSensors)) return undefined;
  const range = await hal.vision.getDistanceSensors();
  return {
    front_m: range.front,
    left_m: range.left,
    right_m: range.right,
    source: range.source ?? 'sensor',
  };
}
