import type { HalCallRecord, SafetyEvent } from './messages.js';
import { TOPICS } from './messages.js';
import type { Recording } from './read-recording.js';

/** What `hal inspect` shows of a recording. */
export interface RecordingSummary {
  /** Whether the file ended properly (false: cut short, read by recovery). */
  complete: boolean;
  /** From the first message to the last, seconds. */
  durationS: number;
  /** Calls recorded, and how many of them failed. */
  calls: number;
  errors: number;
  /** Failed calls by code (a call without a code counts as "ERROR"). */
  errorsByCode: Record<string, number>;
  /** Emergency stops made, and latches seen without a call. */
  emergencyStops: number;
  trips: number;
  /** Messages per topic. */
  channels: Record<string, { schema: string; messages: number }>;
  /** What the recorder lost (from the file's loss record), when it says. */
  dropped?: number;
  /** The recorded robot (from the metadata record `hal.robot`). */
  robot?: Record<string, string>;
}

/** Sums a recording up: duration, calls, errors, e-stops and the messages of each channel. */
export function summarizeRecording(recording: Recording): RecordingSummary {
  const first = recording.messages[0]?.logTime ?? 0n;
  const last = recording.messages.at(-1)?.logTime ?? first;
  const calls = recording.messages
    .filter((m) => m.topic === TOPICS.calls)
    .map((m) => m.value as HalCallRecord);
  const failed = calls.filter((call) => !call.success);
  const errorsByCode: Record<string, number> = {};
  for (const call of failed)
    errorsByCode[call.code ?? 'ERROR'] = (errorsByCode[call.code ?? 'ERROR'] ?? 0) + 1;
  const safety = recording.messages
    .filter((m) => m.topic === TOPICS.safety)
    .map((m) => m.value as SafetyEvent);
  const loss = recording.metadata.get('recorder.loss');
  const robot = recording.metadata.get('hal.robot');
  return {
    complete: recording.complete,
    durationS: Number(last - first) / 1e9,
    calls: calls.length,
    errors: failed.length,
    errorsByCode,
    emergencyStops: safety.filter((e) => e.event === 'emergency_stop' && e.success).length,
    trips: safety.filter((e) => e.event === 'latched').length,
    channels: Object.fromEntries(
      [...recording.channels].map(([topic, c]) => [
        topic,
        { schema: c.schemaName, messages: c.messageCount },
      ]),
    ),
    ...(loss?.['dropped'] !== undefined ? { dropped: Number(loss['dropped']) } : {}),
    ...(robot !== undefined ? { robot } : {}),
  };
}
