import { PoseSchema } from '@hal/types';
import { z } from 'zod';
import type { NamedJsonSchema } from './foxglove-schemas.js';

/*
 * Our own messages: zod schemas, written into the file as JSON Schema (z.toJSONSchema), so every
 * message in a recording can be checked against the schema its channel names.
 */

/** One call through the recorded HAL: what was asked, what came back, and how long it took. */
export const HalCallRecordSchema = z
  .object({
    call: z.string().describe('subsystem and method, e.g. "locomotion.moveTo"'),
    args: z.array(z.unknown()).describe('the arguments as given (long strings shortened)'),
    outcome: z
      .enum(['resolved', 'rejected', 'returned', 'threw'])
      .describe('how the call ended: a promise resolved or rejected, or a synchronous call'),
    success: z
      .boolean()
      .describe("false when the call rejected or threw, or answered a HALToolResult's false"),
    code: z
      .string()
      .optional()
      .describe('the error code (HalErrorCode), when the call failed with one'),
    error: z.string().optional().describe('the error message, when the call failed'),
    result: z.unknown().optional().describe('the value answered (long strings shortened)'),
    pose_after: PoseSchema.optional().describe(
      'the pose read right after a locomotion, manipulation or safety call that answered a HALToolResult (a motion, a stop, an e-stop), for replay',
    ),
    start_ns: z.string().describe('when the call was made, nanoseconds since the epoch'),
    duration_ms: z.number().nonnegative().describe('from the call to its answer, milliseconds'),
  })
  .describe('hal.CallRecord: one HAL call');
export type HalCallRecord = z.infer<typeof HalCallRecordSchema>;

/** An emergency stop, its reset, or a change of the latch seen without a call (a trip). */
export const SafetyEventSchema = z
  .object({
    event: z
      .enum(['emergency_stop', 'reset', 'latched', 'cleared'])
      .describe(
        'emergency_stop / reset: the call was made; latched / cleared: the latch changed ' +
          'without a call through this HAL (a trip on the robot, another controller)',
      ),
    reason: z.string().optional().describe('the reason given with the emergency stop'),
    success: z.boolean().describe('whether the call succeeded (always true for latched/cleared)'),
    code: z.string().optional().describe('the error code of a failed call'),
    emergency_stopped: z.boolean().describe('the latch after the event'),
  })
  .describe('hal.SafetyEvent: an emergency stop, reset or trip');
export type SafetyEvent = z.infer<typeof SafetyEventSchema>;

/** What the recorder lost: written at close, so a reader knows the file is not the whole run. */
export const RecorderLossSchema = z
  .object({
    written: z.number().int().nonnegative().describe('messages written'),
    dropped: z
      .number()
      .int()
      .nonnegative()
      .describe('messages dropped (queue full or disk failed)'),
    reason: z.string().optional().describe('why messages were dropped, when any were'),
  })
  .describe('hal.RecorderLoss: the messages the recorder dropped');
export type RecorderLoss = z.infer<typeof RecorderLossSchema>;

/** One event of an agent run (a model turn, a tool call and its result, token usage, the end). */
export const AgentEventRecordSchema = z
  .looseObject({
    type: z.string().describe("the event's kind, as @hal/agent names it (tool_call, usage, ...)"),
  })
  .describe('hal.AgentEvent: one event of an agent run, as @hal/agent reports it');

function named(name: string, schema: z.ZodType): NamedJsonSchema {
  return { name, schema: z.toJSONSchema(schema, { io: 'input', unrepresentable: 'any' }) };
}

export const CALL_RECORD: NamedJsonSchema = named('hal.CallRecord', HalCallRecordSchema);
export const SAFETY_EVENT: NamedJsonSchema = named('hal.SafetyEvent', SafetyEventSchema);
export const RECORDER_LOSS: NamedJsonSchema = named('hal.RecorderLoss', RecorderLossSchema);
export const HAL_POSE: NamedJsonSchema = named('hal.Pose', PoseSchema);
export const AGENT_EVENT: NamedJsonSchema = named('hal.AgentEvent', AgentEventRecordSchema);

/** The topics a recording of one robot holds. */
export const TOPICS = Object.freeze({
  calls: '/hal/calls',
  pose: '/hal/pose',
  halPose: '/hal/pose/raw',
  tf: '/tf',
  camera: '/hal/camera',
  log: '/hal/log',
  safety: '/hal/safety',
  loss: '/recorder/loss',
  agent: '/agent/events',
});
