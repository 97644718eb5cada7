import type { z } from 'zod';
import { V1_ROBOT } from '../robot-config.js';
import type { RobotConfig } from '../robot-config.js';
import { HAL_CALL_TABLE } from './call-table.js';
import type { CallName, CallSchemas } from './call-table.js';

export type { CallName, CallSchemas } from './call-table.js';

/**
 * The parameter schemas of every HAL call, by name, with limits taken from a robot configuration
 * (each the call table's own, the same object for the same configuration). The `.describe()`
 * texts name units and limits; they become the LLM tool descriptions.
 */
export function createCallSchemas(config: RobotConfig): CallSchemas {
  return Object.fromEntries(
    HAL_CALL_TABLE.map((spec) => [spec.name, spec.paramsSchema(config)]),
  ) as unknown as CallSchemas;
}

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
