import { z } from 'zod';
import { CameraModelSchema } from './camera-model.js';

const finite = z.number();

export const Vector3Schema = z
  .object({ x: finite, y: finite, z: finite })
  .describe('A vector in the robot frame (REP-103: x forward, y left, z up)');
export type Vector3 = z.infer<typeof Vector3Schema>;

/**
 * Where the robot is, which way it faces and how fast it goes. Frame REP-103: x forward, y left,
 * z up; yaw counter-clockwise positive. Position in metres, angles in radians, yaw in (-pi, pi].
 *
 * `confirmed` says whether the robot itself vouches for the pose. A physical HAL dead-reckons
 * between the robot's reports: while a motion runs, or once the link is lost, the pose is the
 * host's prediction (`confirmed: false`), which a robot that lost power or stopped on its host
 * timeout never reached. Show such a pose as predicted, never as measured. A simulator's pose is
 * its own state and leaves the field out.
 */
export const PoseSchema = z
  .object({
    position: z
      .object({
        x: finite.describe('metres, forward from the start'),
        y: finite.describe('metres, left of the start'),
        z: finite.describe('metres, up'),
      })
      .describe('Position, metres'),
    rotation: z
      .object({
        yaw: finite.describe('radians, counter-clockwise positive, (-pi, pi]'),
        pitch: finite.describe('radians'),
        roll: finite.describe('radians'),
      })
      .describe('Orientation, radians'),
    velocity: z
      .object({
        linear: finite.describe('m/s, forward positive'),
        angular: finite.describe('rad/s, counter-clockwise positive'),
      })
      .describe('Current velocity'),
    confirmed: z
      .boolean()
      .optional()
      .describe(
        'false: a prediction the robot has not confirmed (a motion in progress since its last ' +
          'report, or a lost link, after which it may have stopped anywhere short of this); ' +
          "true: the robot's last report, nothing predicted beyond it; absent: the HAL's own " +
          'state (a simulator), with nothing to confirm',
      ),
  })
  .describe('Robot pose, REP-103 frame');
export type Pose = z.infer<typeof PoseSchema>;

/** Where a value comes from, when it is not a direct measurement (e.g. heading from odometry). */
export const ValueSourceSchema = z
  .enum(['sensor', 'odometry', 'simulation', 'unavailable'])
  .describe('Where the reading comes from');
export type ValueSource = z.infer<typeof ValueSourceSchema>;

export const DistanceSensorsSchema = z
  .object({
    front: finite.describe('metres to the nearest obstacle ahead'),
    left: finite.describe('metres to the nearest obstacle on the left'),
    right: finite.describe('metres to the nearest obstacle on the right'),
    frontLeft: finite.optional().describe('metres, 45 degrees left'),
    frontRight: finite.optional().describe('metres, 45 degrees right'),
    limits: z
      .object({
        minM: finite.describe('metres, the shortest distance a sensor reads'),
        maxM: finite.describe('metres, the longest; the reading when nothing is in range'),
        fieldOfViewDeg: finite.describe('degrees, the full cone of each sensor'),
      })
      .optional()
      .describe('What every sensor can see, where the robot knows it'),
    source: ValueSourceSchema.optional(),
  })
  .describe("Range readings, metres (the sensor's maximum range when nothing is in range)");
export type DistanceSensors = z.infer<typeof DistanceSensorsSchema>;

export const IMUReadingSchema = z
  .object({
    acceleration: Vector3Schema.describe('m/s^2, robot frame'),
    gyroscope: Vector3Schema.describe('rad/s, robot frame'),
    heading: finite.describe('radians, counter-clockwise positive, (-pi, pi]'),
    temperature: finite.optional().describe('degrees Celsius, where the IMU has a thermometer'),
    magneticField: Vector3Schema.optional().describe(
      'tesla, robot frame, where the IMU has a magnetometer',
    ),
    source: ValueSourceSchema.optional(),
  })
  .describe('Inertial reading');
export type IMUReading = z.infer<typeof IMUReadingSchema>;

export const DetectedObjectSchema = z
  .object({
    id: z
      .string()
      .describe(
        'a name for this scan only (`seen-1`, `seen-2`, ...); it says nothing of the world',
      ),
    type: z
      .string()
      .describe(
        "what the robot can tell it is: 'obstacle' from range sensors (they cannot tell a box from a robot)",
      ),
    position: Vector3Schema.describe(
      "metres, in the frame of the robot's reported pose (getPose: its odometry, which may drift from the world)",
    ),
    confidence: z.number().min(0).max(1),
    bearingDeg: finite
      .optional()
      .describe('degrees counter-clockwise from where the robot believes it heads, (-180, 180]'),
    distanceM: finite
      .optional()
      .describe(
        "metres from the robot's body to the nearest point seen, as the range sensors read",
      ),
    sizeM: finite.optional().describe('metres, its width across the line of sight, estimated'),
    sensor: z
      .enum(['range', 'camera'])
      .optional()
      .describe('what saw it: the range sensors, or the camera (through a perception layer)'),
  })
  .describe('Something the robot sees');
export type DetectedObject = z.infer<typeof DetectedObjectSchema>;

export const ScanResultSchema = z
  .object({
    objects: z.array(DetectedObjectSchema),
    clearAhead: z.boolean().describe('True when nothing is within the clearance distance ahead'),
    nearestObstacle: finite.optional().describe('metres'),
    frame: z
      .enum(['odometry', 'world'])
      .optional()
      .describe(
        "the frame of the positions: 'odometry', the robot's reported pose (getPose); 'world', a frame the robot knows exactly",
      ),
    source: ValueSourceSchema.optional(),
  })
  .describe('Environment scan');
export type ScanResult = z.infer<typeof ScanResultSchema>;

export const SafetyStatusSchema = z
  .object({
    emergencyStopped: z.boolean(),
    batteryLevel: z.number().min(0).max(100).describe('percent; 100 where the robot has no gauge'),
    temperature: finite.optional().describe('degrees Celsius'),
    batteryVoltage: finite.optional().describe('volts, where the robot measures its supply'),
    batteryCurrent: finite
      .optional()
      .describe('amperes drawn from the supply, where the robot measures it'),
    errors: z.array(z.string()).describe('Active faults and recorded safety trips'),
    emergencyStopReason: z.string().optional(),
  })
  .describe('Safety state');
export type SafetyStatus = z.infer<typeof SafetyStatusSchema>;

export const DeviceInfoSchema = z
  .object({
    id: z.string(),
    type: z.string(),
    mode: z.enum(['simulation', 'physical', 'hybrid']),
    capabilities: z.array(z.string()),
    camera: CameraModelSchema.optional().describe(
      'The camera model its frames are taken with (absent when it has no camera): what ' +
        'perception projects with, so the model travels with the robot',
    ),
  })
  .describe('Who the robot is and what it can do');
export type DeviceInfo = z.infer<typeof DeviceInfoSchema>;
