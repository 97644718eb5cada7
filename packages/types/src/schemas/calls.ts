import { z } from 'zod';
import {
  maxDistancePerCommandCm,
  maxLinearSpeedMPerS,
  maxRotationPerCommandDeg,
  minLinearSpeedMPerS,
  V1_ROBOT,
} from '../robot-config.js';
import type { RobotConfig } from '../robot-config.js';
import { createReadSchemas } from './reads.js';
import { ESTOP_REASON_MAX_BYTES, sanitizeEstopReason } from '../estop-reason.js';

/** Rounds a limit down so the number quoted to users is never above the true limit. */
function floorTo(value: number, decimals: number): number {
  const scale = 10 ** decimals;
  return Math.floor(value * scale) / scale;
}

/** Rounds a lower limit up so the number quoted to users is never below the true limit. */
function ceilTo(value: number, decimals: number): number {
  const scale = 10 ** decimals;
  return Math.ceil(value * scale) / scale;
}

/**
 * The parameter schemas of every HAL call, with limits taken from a robot configuration. The
 * `.describe()` texts name units and limits; they become the LLM tool descriptions.
 */
export function createCallSchemas(config: RobotConfig) {
  const maxCm = floorTo(maxDistancePerCommandCm(config), 1);
  const maxDeg = floorTo(maxRotationPerCommandDeg(config), 1);
  const maxSpeed = floorTo(maxLinearSpeedMPerS(config), 4);
  const minSpeed = Math.min(ceilTo(minLinearSpeedMPerS(config), 4), maxSpeed);
  const extent = config.workspaceHalfExtentM;
  const power = (wheel: string) =>
    z
      .number()
      .min(-255)
      .max(255)
      .describe(`${wheel} wheel power, -255..255 (negative: backwards; 255 = top speed)`);
  const distanceCm = z
    .number()
    .gt(0)
    .max(maxCm)
    .describe(`Distance, cm, greater than 0 and at most ${maxCm} (one command's limit)`);

  return {
    ...createReadSchemas(),
    drive: z
      .object({
        left: power('Left'),
        right: power('Right'),
        durationMs: z
          .number()
          .gt(0)
          .max(config.maxDriveDurationMs)
          .optional()
          .describe(
            `Stop after this many ms, at most ${config.maxDriveDurationMs}; omit to drive until stop()`,
          ),
      })
      .describe('Drive the wheels at the given powers'),
    moveTo: z
      .object({
        x: z.number().min(-extent).max(extent).describe(`Target x, metres, -${extent}..${extent}`),
        y: z.number().min(-extent).max(extent).describe(`Target y, metres, -${extent}..${extent}`),
        z: z.number().describe('Target z, metres (ignored by wheeled robots)'),
        speed: z
          .number()
          .min(minSpeed)
          .max(maxSpeed)
          .optional()
          .describe(
            `Cruise speed, m/s, ${minSpeed}..${maxSpeed} (the robot's slowest and top speeds); default top speed`,
          ),
      })
      .describe('Turn toward a point and drive straight to it (REP-103: x forward, y left)'),
    rotate: z
      .object({
        direction: z
          .enum(['left', 'right'])
          .describe('left: counter-clockwise (yaw increases); right: clockwise'),
        degrees: z
          .number()
          .gt(0)
          .max(maxDeg)
          .describe(`Angle, degrees, greater than 0 and at most ${maxDeg}`),
      })
      .describe('Turn in place'),
    moveForward: z.object({ distanceCm }).describe('Drive straight ahead'),
    moveBackward: z.object({ distanceCm }).describe('Drive straight back'),
    stop: z.object({}).describe('Stop all wheel motion now'),
    speak: z
      .object({
        text: z.string().min(1).max(500).describe('What to say, 1..500 characters'),
        urgency: z.enum(['info', 'warning', 'alert']).optional().describe('How to say it'),
      })
      .describe('Say something through the speaker'),
    setLED: z
      .object({
        r: z.number().int().min(0).max(255).describe('Red, 0..255'),
        g: z.number().int().min(0).max(255).describe('Green, 0..255'),
        b: z.number().int().min(0).max(255).describe('Blue, 0..255'),
        pattern: z
          .enum(['solid', 'blink', 'pulse'])
          .optional()
          .describe('Light pattern, default solid'),
      })
      .describe('Set the status LED'),
    playSound: z
      .object({ soundId: z.string().min(1).max(100).describe('Sound effect id') })
      .describe('Play a sound effect'),
    emergencyStop: z
      .object({
        // never refused for its argument: any value becomes a stored reason (estop-reason.ts)
        reason: z
          .preprocess(sanitizeEstopReason, z.string().max(ESTOP_REASON_MAX_BYTES))
          .describe(
            `Why (optional text; control characters become spaces, cut to ${ESTOP_REASON_MAX_BYTES} UTF-8 bytes)`,
          ),
      })
      .describe('Stop everything and latch until reset; never refused for its argument'),
    resetEmergencyStop: z.object({}).describe('Clear a latched emergency stop'),
  } as const;
}

/** The call schemas for a robot configuration. */
export type CallSchemas = ReturnType<typeof createCallSchemas>;
/** The name of a validated HAL call. */
export type CallName = keyof CallSchemas;
/** The validated parameters of a HAL call. */
export type CallParams<N extends CallName> = z.output<CallSchemas[N]>;

/** The call schemas of the V1 robot, for tool definitions and documentation. */
export const V1_CALL_SCHEMAS: CallSchemas = createCallSchemas(V1_ROBOT);

export const DriveParamsSchema = V1_CALL_SCHEMAS.drive;
export type DriveParams = z.infer<typeof DriveParamsSchema>;
export const MoveToParamsSchema = V1_CALL_SCHEMAS.moveTo;
export type MoveToParams = z.infer<typeof MoveToParamsSchema>;
export const RotateParamsSchema = V1_CALL_SCHEMAS.rotate;
export type RotateParams = z.infer<typeof RotateParamsSchema>;
export const MoveDistanceParamsSchema = V1_CALL_SCHEMAS.moveForward;
export type MoveDistanceParams = z.infer<typeof MoveDistanceParamsSchema>;
export const SpeakParamsSchema = V1_CALL_SCHEMAS.speak;
export type SpeakParams = z.infer<typeof SpeakParamsSchema>;
export const SetLEDParamsSchema = V1_CALL_SCHEMAS.setLED;
export type SetLEDParams = z.infer<typeof SetLEDParamsSchema>;
export const PlaySoundParamsSchema = V1_CALL_SCHEMAS.playSound;
export type PlaySoundParams = z.infer<typeof PlaySoundParamsSchema>;
export const EmergencyStopParamsSchema = V1_CALL_SCHEMAS.emergencyStop;
export type EmergencyStopParams = z.infer<typeof EmergencyStopParamsSchema>;
