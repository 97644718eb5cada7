import { z } from 'zod';
import type { CallName } from './calls.js';
import { READ_RESULT_SCHEMAS } from './reads.js';

/** Where the robot ended up, as result data: metres and radians (REP-103). */
const PoseDataSchema = z.looseObject({
  x: z.number().describe('metres'),
  y: z.number().describe('metres'),
  yaw: z.number().describe('radians, counter-clockwise positive'),
});

/** What a motion reports; each world may add more (steps, move ids, divergence). */
export const MOTION_DATA_SCHEMA: z.ZodType = z.looseObject({ pose: PoseDataSchema.optional() });

const LedSchema = z.looseObject({
  r: z.number().int().min(0).max(255),
  g: z.number().int().min(0).max(255),
  b: z.number().int().min(0).max(255),
  pattern: z.enum(['solid', 'blink', 'pulse']),
});

/**
 * The `data` of a successful result of every call but the plain motions (which answer
 * {@link MOTION_DATA_SCHEMA}), or the value a value call answers with: the shape both worlds
 * share (loose objects: a world may add fields, never rename them).
 */
export const CALL_DATA_SCHEMAS: Readonly<Partial<Record<CallName, z.ZodType>>> = Object.freeze({
  ...READ_RESULT_SCHEMAS,
  drive: z.looseObject({
    leftSps: z.number().describe('left wheel speed, steps/s'),
    rightSps: z.number().describe('right wheel speed, steps/s'),
    running: z.boolean().describe('the wheels keep turning after the call answered'),
  }),
  stop: z.looseObject({ stopped: z.boolean(), pose: PoseDataSchema.optional() }),
  speak: z.looseObject({ spoken: z.string() }),
  setLED: z.looseObject({ led: LedSchema }),
  playSound: z.looseObject({ soundId: z.string() }),
  emergencyStop: z.looseObject({ estop: z.literal(true), reason: z.string() }),
  resetEmergencyStop: z.looseObject({
    estop: z.literal(false),
    wasEmergencyStopped: z.boolean().describe('the emergency stop was latched before the reset'),
  }),
  log: z.undefined().describe('log answers nothing'),
});
