import { z } from 'zod';

/** A {@link GuardStop} as a schema (for recordings: the `/hal/guard` topic). */
export const GuardStopSchema = z
  .object({
    motion: z.string().describe('The call: moveForward, moveTo, drive'),
    distanceM: z.number().describe("Free distance seen ahead of the body's front, metres"),
    source: z.enum(['camera', 'range']).describe('What saw it'),
    atEdge: z.boolean().describe('What was seen reached the edge of the view: at most distanceM'),
    when: z.enum(['before', 'during']).describe('Refused (nothing moved) or stopped on the way'),
    travelledM: z.number().describe('How far the robot went in this call, metres'),
    at: z.number().describe('When, ms since the epoch'),
  })
  .describe('A motion the guard refused or stopped for an obstacle ahead');

/** A {@link GuardEvent} as a schema. */
export const GuardEventSchema = z
  .discriminatedUnion('type', [
    z.object({ type: z.literal('obstacle'), stop: GuardStopSchema }),
    z.object({
      type: z.literal('blind'),
      motion: z.string(),
      message: z.string(),
      at: z.number(),
    }),
    z.object({
      type: z.literal('unguarded'),
      motion: z.string(),
      message: z.string(),
      at: z.number(),
    }),
    z.object({ type: z.literal('cannot-guard'), message: z.string(), at: z.number() }),
  ])
  .describe('What the guard did: a stop, a blind stop, a motion it could not watch, it cannot see');
