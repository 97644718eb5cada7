import { z } from 'zod';

// The pieces of result data several calls share; each call's own `data` is in call-table.ts.

/** Where the robot ended up, as result data: metres and radians (REP-103). */
export const PoseDataSchema = z.looseObject({
  x: z.number().describe('metres'),
  y: z.number().describe('metres'),
  yaw: z.number().describe('radians, counter-clockwise positive'),
});

/** What a motion reports; each world may add more (steps, move ids, divergence). */
export const MOTION_DATA_SCHEMA: z.ZodType = z.looseObject({ pose: PoseDataSchema.optional() });

/** The LED's state as result data. */
export const LedDataSchema = z.looseObject({
  r: z.number().int().min(0).max(255),
  g: z.number().int().min(0).max(255),
  b: z.number().int().min(0).max(255),
  pattern: z.enum(['solid', 'blink', 'pulse']),
});
