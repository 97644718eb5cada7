import { z } from 'zod';
import type { HALLogLevel, VisionInterface } from '../interfaces.js';
import {
  DistanceSensorsSchema,
  IMUReadingSchema,
  PoseSchema,
  SafetyStatusSchema,
  ScanResultSchema,
} from '../pose.js';

/** The longest message `communication.log` takes, characters. */
export const MAX_LOG_MESSAGE_LENGTH = 2000;

/** The levels of `communication.log`. */
export const LOG_LEVELS = [
  'debug',
  'info',
  'warn',
  'error',
] as const satisfies readonly HALLogLevel[];

/** The ways `vision.scan` can look around. */
export const SCAN_MODES = ['full', 'targeted', 'quick'] as const satisfies readonly NonNullable<
  Parameters<VisionInterface['scan']>[0]
>[];

/**
 * The parameter schemas of the calls that read state (and of `log`), which answer with a value
 * rather than a result. They depend on no robot limit; the `.describe()` texts say what each call
 * returns, in which units and frame, for LLM tool descriptions.
 */
export function createReadSchemas() {
  return {
    getPose: z
      .object({})
      .describe(
        'Read the pose, REP-103 frame (x forward, y left, yaw counter-clockwise positive): ' +
          'position in metres, yaw/pitch/roll in radians (yaw in (-pi, pi]), ' +
          'linear velocity in m/s, angular velocity in rad/s',
      ),
    captureFrame: z
      .object({})
      .describe(
        'Capture the latest camera frame, a base64 JPEG data URL (320x240 on the V1 robot)',
      ),
    scan: z
      .object({
        mode: z
          .enum(SCAN_MODES)
          .optional()
          .describe(
            'full: all around; targeted: the sector ahead; quick: front, left and right (default)',
          ),
      })
      .describe(
        'Scan the surroundings for obstacles with the range sensors: what they see within their range, ' +
          "distances in metres, positions in the frame of the robot's reported pose (getPose)",
      ),
    getDistanceSensors: z
      .object({})
      .describe(
        'Read the range sensors: metres to the nearest obstacle front, left and right ' +
          "(the sensor's maximum range when nothing is in range)",
      ),
    getLineSensors: z
      .object({})
      .describe('Read the line sensors, 0..1 each (1: line seen), left to right'),
    getIMU: z
      .object({})
      .describe(
        'Read the IMU: acceleration m/s^2 and rotation rate rad/s in the robot frame, heading in ' +
          'radians counter-clockwise positive; source says whether it is measured or from odometry',
      ),
    getSafetyStatus: z
      .object({})
      .describe(
        'Read the safety state: whether the emergency stop is latched and why, battery percent ' +
          '0..100, temperature in degrees Celsius where measured, active faults and recorded trips',
      ),
    isEmergencyStopped: z
      .object({})
      .describe('Whether the emergency stop is latched (motion is refused until it is reset)'),
    log: z
      .object({
        message: z
          .string()
          .max(MAX_LOG_MESSAGE_LENGTH)
          .describe(`The message, up to ${MAX_LOG_MESSAGE_LENGTH} characters`),
        level: z.enum(LOG_LEVELS).optional().describe('Severity, default info'),
      })
      .describe("Record a message in the HAL's log and telemetry"),
  } as const;
}

/** The calls that answer with a value, not a result (see {@link createReadSchemas}). */
export type ReadCallName = Exclude<keyof ReturnType<typeof createReadSchemas>, 'log'>;

/** A camera frame: a base64 JPEG data URL. */
export const FrameDataUrlSchema = z
  .string()
  .regex(/^data:image\/jpeg;base64,[A-Za-z0-9+/]+=*$/)
  .describe('A camera frame, `data:image/jpeg;base64,...`');

/** Line sensor readings, 0..1 each, left to right. */
export const LineSensorsSchema = z
  .array(z.number().min(0).max(1))
  .describe('Line sensor readings, 0..1 each, left to right');

/**
 * What each value-returning call answers with, for checking results (tests, remote clients) and
 * for tool definitions. `log` answers nothing.
 */
export const READ_RESULT_SCHEMAS = {
  getPose: PoseSchema,
  captureFrame: FrameDataUrlSchema,
  scan: ScanResultSchema,
  getDistanceSensors: DistanceSensorsSchema,
  getLineSensors: LineSensorsSchema,
  getIMU: IMUReadingSchema,
  getSafetyStatus: SafetyStatusSchema,
  isEmergencyStopped: z.boolean().describe('True while the emergency stop is latched'),
} as const satisfies Record<ReadCallName, z.ZodType>;

const V1_READ_SCHEMAS = createReadSchemas();

export const ScanParamsSchema = V1_READ_SCHEMAS.scan;
export type ScanParams = z.infer<typeof ScanParamsSchema>;
export const LogParamsSchema = V1_READ_SCHEMAS.log;
export type LogParams = z.infer<typeof LogParamsSchema>;
/** The parameters of a call that takes none (getPose, captureFrame, getIMU, ...). */
export const NoParamsSchema = V1_READ_SCHEMAS.getPose;
export type NoParams = z.infer<typeof NoParamsSchema>;
