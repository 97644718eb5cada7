import type { HardwareAbstractionLayer, Pose } from '@hal/types';
import type { HalCallRecord } from './messages.js';
import { robotNamespace } from './namespace.js';
import type { Recording } from './read-recording.js';

/** One recorded call run again, and how far the replay ended from the recording. */
export interface ReplayedCall {
  call: string;
  args: unknown[];
  recorded: { success: boolean; code?: string };
  replayed: { success: boolean; code?: string };
  /** Planar distance between the recorded and the replayed pose after the call, metres. */
  positionM?: number;
  /** Their yaw difference, radians, in (-pi, pi]. */
  yawRad?: number;
  /** Wheel steps the two reported for the call (`leftSteps`/`rightSteps`), where both did. */
  steps?: { recorded: [number, number]; replayed: [number, number] };
  recordedPose?: Pose;
  replayedPose?: Pose;
}

/** A replay: every action call, and the largest divergence. */
export interface ReplayReport {
  calls: ReplayedCall[];
  maxPositionM: number;
  maxYawRad: number;
  /** Calls whose outcome (success, code) differs between recording and replay. */
  outcomeMismatches: number;
  /** Calls whose reported steps differ. */
  stepMismatches: number;
}

function isActionRecord(record: HalCallRecord): boolean {
  const result = record.result as { success?: unknown; mode?: unknown } | undefined;
  const subsystem = record.call.split('.')[0];
  return (
    record.call.includes('.') &&
    subsystem !== undefined &&
    typeof result?.success === 'boolean' &&
    typeof result.mode === 'string'
  );
}

function stepsOf(result: unknown): [number, number] | undefined {
  const data = (result as { data?: { leftSteps?: unknown; rightSteps?: unknown } } | undefined)
    ?.data;
  return typeof data?.leftSteps === 'number' && typeof data.rightSteps === 'number'
    ? [data.leftSteps, data.rightSteps]
    : undefined;
}

const wrap = (a: number): number => Math.atan2(Math.sin(a), Math.cos(a));

/**
 * Runs a recording's action calls (every call that answered a HALToolResult: motions, stops,
 * e-stops and resets, LED...) again, in order, on `hal` (initialised, at the recording's start),
 * and measures after each how far its pose is from the pose recorded after the same call.
 * Reads are not replayed: they change nothing. In a recording of several robots, `namespace`
 * names the one to replay (its calls on `/<namespace>/hal/calls`).
 */
export async function replayRecording(
  recording: Recording,
  hal: HardwareAbstractionLayer,
  options: { namespace?: string } = {},
): Promise<ReplayReport> {
  const topic = robotNamespace(options.namespace).topics.calls;
  const records = recording.messages
    .filter((m) => m.topic === topic)
    .map((m) => m.value as HalCallRecord)
    .filter(isActionRecord);
  const calls: ReplayedCall[] = [];
  for (const record of records) {
    const [subsystem, method] = record.call.split('.') as [string, string];
    const target = (hal as unknown as Record<string, Record<string, unknown> | undefined>)[
      subsystem
    ];
    const fn = target?.[method];
    let replayedResult: unknown;
    if (typeof fn === 'function') {
      replayedResult = await Promise.resolve(
        (fn as (...args: unknown[]) => unknown).apply(target, record.args),
      ).catch((error: unknown) => ({ success: false, code: (error as { code?: string }).code }));
    } else {
      replayedResult = { success: false, code: 'NOT_IMPLEMENTED' };
    }
    const replayed = replayedResult as { success: boolean; code?: string };
    const replayedPose = await hal.locomotion.getPose().catch(() => undefined);
    const entry: ReplayedCall = {
      call: record.call,
      args: record.args,
      recorded: {
        success: record.success,
        ...(record.code !== undefined ? { code: record.code } : {}),
      },
      replayed: {
        success: replayed.success,
        ...(replayed.code !== undefined ? { code: replayed.code } : {}),
      },
    };
    const recordedPose = record.pose_after;
    if (recordedPose && replayedPose) {
      entry.positionM = Math.hypot(
        recordedPose.position.x - replayedPose.position.x,
        recordedPose.position.y - replayedPose.position.y,
      );
      entry.yawRad = wrap(recordedPose.rotation.yaw - replayedPose.rotation.yaw);
      entry.recordedPose = recordedPose;
      entry.replayedPose = replayedPose;
    }
    const recordedSteps = stepsOf(record.result);
    const replayedSteps = stepsOf(replayedResult);
    if (recordedSteps && replayedSteps)
      entry.steps = { recorded: recordedSteps, replayed: replayedSteps };
    calls.push(entry);
  }
  return {
    calls,
    maxPositionM: Math.max(0, ...calls.map((c) => c.positionM ?? 0)),
    maxYawRad: Math.max(0, ...calls.map((c) => Math.abs(c.yawRad ?? 0))),
    outcomeMismatches: calls.filter(
      (c) => c.recorded.success !== c.replayed.success || c.recorded.code !== c.replayed.code,
    ).length,
    stepMismatches: calls.filter(
      (c) =>
        c.steps &&
        (c.steps.recorded[0] !== c.steps.replayed[0] ||
          c.steps.recorded[1] !== c.steps.replayed[1]),
    ).length,
  };
}
