import type { Logger, RobotConfig } from '@hal/types';
import type { CameraOptions } from '../camera.js';
import type { ImuOptions } from '../gyro.js';
import type { BodyErrorInput } from '../robot/body-error.js';
import type { JpegEncoder } from '../jpeg-encoders.js';
import type { SimRobot } from '../robot/sim-robot.js';
import type { RangeSensorOptions } from '../sensors.js';
import type { World } from '../world.js';

/** Renders a robot's camera frame as a `data:image/jpeg;base64,...` URL. */
export type FrameSource = (world: World, robot: SimRobot) => Promise<string>;

/** How the HAL waits for a motion to end. */
export type SimulationClock =
  /** The HAL advances the world's clock itself until the motion ends: faster than real time. */
  | 'fast'
  /** A real-time ticker advances the clock (`world.startRealtime`, started by the HAL if off). */
  | 'realtime'
  /** Someone else steps the world (`world.step()`); the HAL only waits. */
  | 'manual';

/** What the simulated robot has besides wheels, an LED and an e-stop. */
export interface SimulatedFeatures {
  /** A camera (`captureFrame`). Default true. */
  camera?: boolean;
  /** Range sensors front/left/right (`getDistanceSensors`, `scan`). Default true. */
  rangeSensors?: boolean;
  /** An IMU (`getIMU` with source 'simulation'; without one, heading from odometry). Default true. */
  imu?: boolean;
  /** A speaker (`speak`, `playSound` emit events). Default false, like the V1 robot. */
  speaker?: boolean;
}

export interface SimulationHALOptions {
  /** The world to live in; default a new world on the `empty` map. */
  world?: World;
  /** The id of an existing robot in `world` to drive; default a new robot is added. */
  robotId?: string;
  /** Geometry and limits of a newly added robot; default the V1 robot. */
  robot?: Partial<RobotConfig>;
  /** Start pose of a newly added robot; default the map's start. */
  start?: { x: number; y: number; yaw: number };
  /**
   * How a newly added robot's body differs from the nominal one: wheel diameters, slip, odometry
   * error (see {@link BodyErrorInput}). The world then has the robot where its body really went,
   * while the HAL reports the robot's odometry (`getPose`, the pose in results). Default none.
   */
  bodyError?: BodyErrorInput;
  /** How motions are waited for. Default 'fast'. */
  clock?: SimulationClock;
  /** Speed of the ticker the HAL starts in 'realtime' mode. Default 1. */
  realtimeSpeed?: number;
  /** 'manual' mode: fail a motion with TIMEOUT when the clock has not moved for this long, ms. Default 60000. */
  manualTimeoutMs?: number;
  /** 'realtime' mode: fail a motion with TIMEOUT when the ticker has stalled this long, ms. Default 5000. */
  stallTimeoutMs?: number;
  /** Extra features of the simulated robot. */
  features?: SimulatedFeatures;
  /** Range sensor model. */
  rangeSensors?: RangeSensorOptions;
  /**
   * The IMU's errors: gyro bias and noise, accelerometer noise (see {@link ImuOptions}; by default
   * those of a consumer MEMS IMU, so the heading drifts from the true yaw; all 0: a perfect IMU).
   */
  imu?: ImuOptions;
  /** Camera model of the built-in software renderer. */
  camera?: CameraOptions;
  /**
   * Encodes the software renderer's frames; default the fastest the runtime has (sharp in Node
   * when installed, the browser's canvas encoder, else jpeg-js).
   */
  jpegEncoder?: JpegEncoder;
  /** Renders frames another way (the browser demo uses Three.js). */
  frameSource?: FrameSource;
  /** Device id reported by `getDeviceInfo`. Default `sim-` + the robot id. */
  deviceId?: string;
  /** Where the HAL writes (namespace `hal:simulation`), never the console. Default silent. */
  logger?: Logger;
}

/** Every default of a SimulationHAL, in one place (the options above say how each is used). */
export const SIMULATION_HAL_DEFAULTS = Object.freeze({
  clock: 'fast' as SimulationClock,
  realtimeSpeed: 1,
  /** 'manual' clock: a motion fails TIMEOUT when the clock has not moved for this long, ms. */
  manualTimeoutMs: 60_000,
  /** 'realtime' clock: a motion fails TIMEOUT when the ticker has stalled this long, ms. */
  stallTimeoutMs: 5000,
  /** The V1 robot's parts, but for the simulator's sensors: a camera, range sensors, an IMU. */
  features: Object.freeze({ camera: true, rangeSensors: true, imu: true, speaker: false }),
});

/** The features a robot has: those asked for, the rest by default (all but the speaker). */
export function resolveFeatures(features: SimulatedFeatures = {}): Required<SimulatedFeatures> {
  const defaults = SIMULATION_HAL_DEFAULTS.features;
  return {
    camera: features.camera ?? defaults.camera,
    rangeSensors: features.rangeSensors ?? defaults.rangeSensors,
    imu: features.imu ?? defaults.imu,
    speaker: features.speaker ?? defaults.speaker,
  };
}
