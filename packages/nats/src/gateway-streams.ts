import { CAPABILITIES, hasCapability } from '@hal/types';
import type { DistanceSensors, HardwareAbstractionLayer, RobotConfig } from '@hal/types';
import { wheelVelocities } from './drive-mapping.js';
import type { DifferentialState, ImuData, RangeData, RangeSummary } from './messages.js';

/** The state stream's payload, read from the HAL; supply voltage and current only where known. */
export async function readDifferentialState(
  hal: HardwareAbstractionLayer,
  robot: RobotConfig,
): Promise<DifferentialState> {
  const pose = await hal.locomotion.getPose();
  const safety = hal.safety.getSafetyStatus();
  const state: DifferentialState = {
    ...wheelVelocities(pose.velocity.linear, pose.velocity.angular, robot),
    linear_vel_m_per_s: pose.velocity.linear,
    angular_vel_rad_per_s: pose.velocity.angular,
    x_m: pose.position.x,
    y_m: pose.position.y,
    yaw_rad: pose.rotation.yaw,
    emergency_stopped: safety.emergencyStopped,
    timestamp_ms: Date.now(),
  };
  if (safety.batteryVoltage !== undefined) state.battery_volts = safety.batteryVoltage;
  if (safety.batteryCurrent !== undefined) state.current_amps = safety.batteryCurrent;
  return state;
}

/** Which of the optional streams a device's capabilities offer. */
export interface OfferedStreams {
  imu: boolean;
  range: boolean;
}

/** The optional streams `capabilities` offer (parsed capability strings: a gateway caches this). */
export function offersStream(capabilities: readonly string[]): OfferedStreams {
  return {
    imu: hasCapability(capabilities, CAPABILITIES.imu),
    range: hasCapability(capabilities, CAPABILITIES.rangeSensors),
  };
}

/** The orientation of a heading about the z axis (REP-103, z up) as the spec's `{w,x,y,z}`. */
export function quaternionFromHeading(headingRad: number): ImuData['orientation_quaternion'] {
  return { w: Math.cos(headingRad / 2), x: 0, y: 0, z: Math.sin(headingRad / 2) };
}

/** The IMU stream's payload, or undefined when the device offers no IMU (nothing is streamed). */
export async function readImu(
  hal: HardwareAbstractionLayer,
  offered = offersStream(hal.getDeviceInfo().capabilities).imu,
): Promise<ImuData | undefined> {
  if (!offered) return undefined;
  const imu = await hal.vision.getIMU();
  const data: ImuData = {
    orientation_quaternion: quaternionFromHeading(imu.heading),
    accel_m_per_s2: imu.acceleration,
    gyro_rad_per_s: imu.gyroscope,
    heading_rad: imu.heading,
    source: imu.source ?? 'sensor',
  };
  // only what the IMU has: a missing thermometer or magnetometer is absent, never a made-up 0
  if (imu.temperature !== undefined) data.temperature_celsius = imu.temperature;
  if (imu.magneticField !== undefined) data.mag_tesla = imu.magneticField;
  return data;
}

/** Both forms of one range reading: the spec's one message per sensor, and ours. */
export interface RangeMessages {
  perSensor: RangeData[];
  summary: RangeSummary;
}

const SENSORS = [
  ['front', 'front'],
  ['left', 'left'],
  ['right', 'right'],
  ['front_left', 'frontLeft'],
  ['front_right', 'frontRight'],
] as const satisfies readonly (readonly [string, keyof DistanceSensors])[];

/**
 * The spec's one-sensor messages for a reading. Without the HAL's `limits` the sensors' range and
 * field of view are unknown, and no spec message can be made honestly: none is.
 */
export function rangePerSensor(range: DistanceSensors): RangeData[] {
  const limits = range.limits;
  if (limits === undefined) return [];
  const out: RangeData[] = [];
  for (const [sensor, key] of SENSORS) {
    const distance = range[key];
    if (typeof distance !== 'number') continue;
    out.push({
      sensor,
      distance_m: distance,
      min_range_m: limits.minM,
      max_range_m: limits.maxM,
      fov_deg: limits.fieldOfViewDeg,
      // the reading is the maximum when nothing is in range: nothing was seen there
      confidence: distance < limits.maxM ? 1 : 0,
      source: range.source ?? 'sensor',
    });
  }
  return out;
}

/** The range streams' payloads, or undefined when the device offers no range sensors. */
export async function readRange(
  hal: HardwareAbstractionLayer,
  offered = offersStream(hal.getDeviceInfo().capabilities).range,
): Promise<RangeMessages | undefined> {
  if (!offered) return undefined;
  const range = await hal.vision.getDistanceSensors();
  return {
    perSensor: rangePerSensor(range),
    summary: {
      front_m: range.front,
      left_m: range.left,
      right_m: range.right,
      source: range.source ?? 'sensor',
    },
  };
}
