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
      'the pose read right after a locomotion, manipulation or safety call that answered a HALToolResult (a motion, a stop, an e-stop), and after initialize (where the run starts), for replay',
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

/** A physical robot's wheel counters as the robot itself reported them (never the prediction). */
export const WheelStepsSchema = z
  .object({
    left_steps: z
      .number()
      .int()
      .describe("the left wheel's absolute step counter, as the robot last reported it"),
    right_steps: z
      .number()
      .int()
      .describe("the right wheel's absolute step counter, as the robot last reported it"),
    left_steps_per_s: z.number().describe("the left wheel's speed in that report, steps/s"),
    right_steps_per_s: z.number().describe("the right wheel's speed in that report, steps/s"),
    robot_uptime_ms: z
      .number()
      .nonnegative()
      .describe("the robot's uptime in its last status reply, ms (it goes back after a restart)"),
  })
  .describe("hal.WheelSteps: a physical robot's reported step counters");
export type WheelSteps = z.infer<typeof WheelStepsSchema>;

const count = (what: string) => z.number().int().nonnegative().describe(what);

/** The link to a physical robot: its round trips so far, and on serial its frames. */
export const LinkStatsSchema = z
  .object({
    link_state: z
      .string()
      .describe('connected, lost (reconnecting), closed, or idle before initialize'),
    sent: count('requests sent, resends included'),
    received: count('replies that answered a pending request'),
    retries: count('resends of a request after its reply did not come in time'),
    timeouts: count('requests given up after every attempt'),
    unanswered: count(
      'requests sent (resends included) that no reply answered: lost on the way out or back, or still waiting',
    ),
    dropped: count('inbound messages dropped: undecodable, failed MAC, or answering nothing'),
    rtt_p50_ms: z.number().nonnegative().describe('median round trip of answered requests, ms'),
    rtt_p99_ms: z.number().nonnegative().describe('99th percentile round trip, ms'),
    serial: z
      .object({
        frames_sent: count('frames sent'),
        frames_received: count('frames received'),
        acks_sent: count('ACK frames sent'),
        acks_received: count('ACK frames received'),
        frame_retries: count('frames resent because their ACK did not come in time'),
        frame_timeouts: count('frames given up after every attempt'),
        checksum_errors: count('frames with a bad CRC-16'),
        resync_bytes: count('bytes skipped while hunting for a frame'),
        duplicate_frames: count('duplicate DATA frames acknowledged but not delivered again'),
      })
      .optional()
      .describe("the serial link's frame statistics (absent on UDP)"),
  })
  .describe("hal.LinkStats: a physical robot's link statistics (round trips, retries, RTT)");
export type LinkStats = z.infer<typeof LinkStatsSchema>;

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
export const WHEEL_STEPS: NamedJsonSchema = named('hal.WheelSteps', WheelStepsSchema);
export const LINK_STATS: NamedJsonSchema = named('hal.LinkStats', LinkStatsSchema);

/** The topics a recording of one robot holds. */
export const TOPICS = Object.freeze({
  calls: '/hal/calls',
  pose: '/hal/pose',
  halPose: '/hal/pose/raw',
  tf: '/tf',
  camera: '/hal/camera',
  log: '/hal/log',
  safety: '/hal/safety',
  steps: '/hal/steps',
  link: '/hal/link',
  loss: '/recorder/loss',
  agent: '/agent/events',
});
