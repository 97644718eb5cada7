import type { HalCallRecord, SafetyEvent } from './messages.js';
import { TOPICS } from './messages.js';
import { namespaceOfCallTopic } from './namespace.js';
import type { Recording } from './read-recording.js';
import type { RecordingGap } from './recover-records.js';

/** The counts of one robot in a recording of several. */
export interface RobotSummary {
  calls: number;
  errors: number;
  emergencyStops: number;
  trips: number;
  /** Messages on the robot's own topics (`/<namespace>/...`). */
  messages: number;
}

/** What `hal inspect` shows of a recording. */
export interface RecordingSummary {
  /** Whether the file ended properly (false: cut short or damaged, read by recovery). */
  complete: boolean;
  /** What could not be read: where the file was cut short or damaged (empty when complete). */
  gaps: RecordingGap[];
  /** The reading's own account of a file not read whole (where it stopped, what it read). */
  truncation?: string;
  /** The file's size in bytes. */
  fileBytes: number;
  /** From the first message to the last, seconds. */
  durationS: number;
  /** Calls recorded (of every robot), and how many of them failed. */
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
  /** A recording of several robots (a fleet): each one's counts, by namespace. */
  robots?: Record<string, RobotSummary>;
}

/** The namespace of a robot's topic (`/sim-1/hal/safety` -> `sim-1`, `/hal/safety` -> ''). */
function namespaceOf(topic: string, own: string): string | undefined {
  if (topic === own) return '';
  const match = /^\/([A-Za-z0-9_-]{1,64})(\/.*)$/.exec(topic);
  return match?.[2] === own ? match[1] : undefined;
}

function tally(calls: HalCallRecord[], safety: SafetyEvent[]) {
  return {
    calls: calls.length,
    errors: calls.filter((call) => !call.success).length,
    emergencyStops: safety.filter((e) => e.event === 'emergency_stop' && e.success).length,
    trips: safety.filter((e) => e.event === 'latched').length,
  };
}

/**
 * Sums a recording up: duration, calls, errors, e-stops and the messages of each channel; for a
 * recording of several robots (namespaced topics, as `hal fleet run --record` writes) each
 * robot's counts too.
 */
export function summarizeRecording(recording: Recording): RecordingSummary {
  const first = recording.messages[0]?.logTime ?? 0n;
  const last = recording.messages.at(-1)?.logTime ?? first;
  const callsBy = new Map<string, HalCallRecord[]>();
  const safetyBy = new Map<string, SafetyEvent[]>();
  const add = <T>(map: Map<string, T[]>, key: string, value: T): void => {
    const list = map.get(key);
    if (list === undefined) map.set(key, [value]);
    else list.push(value);
  };
  for (const m of recording.messages) {
    const callSpace = namespaceOfCallTopic(m.topic);
    if (callSpace !== undefined) add(callsBy, callSpace, m.value as HalCallRecord);
    const safetySpace = namespaceOf(m.topic, TOPICS.safety);
    if (safetySpace !== undefined) add(safetyBy, safetySpace, m.value as SafetyEvent);
  }
  const calls = [...callsBy.values()].flat();
  const failed = calls.filter((call) => !call.success);
  const errorsByCode: Record<string, number> = {};
  for (const call of failed)
    errorsByCode[call.code ?? 'ERROR'] = (errorsByCode[call.code ?? 'ERROR'] ?? 0) + 1;
  const total = tally(calls, [...safetyBy.values()].flat());

  const spaces = [...callsBy.keys()].filter((space) => space !== '').sort();
  const robots: Record<string, RobotSummary> = {};
  for (const space of spaces) {
    let messages = 0;
    for (const [topic, channel] of recording.channels) {
      if (topic.startsWith(`/${space}/`)) messages += channel.messageCount;
    }
    robots[space] = {
      ...tally(callsBy.get(space) ?? [], safetyBy.get(space) ?? []),
      messages,
    };
  }

  const loss = recording.metadata.get('recorder.loss');
  const robot = recording.metadata.get('hal.robot');
  return {
    complete: recording.complete,
    gaps: recording.gaps,
    ...(recording.truncation === undefined ? {} : { truncation: recording.truncation }),
    fileBytes: recording.fileBytes,
    durationS: Number(last - first) / 1e9,
    ...total,
    errorsByCode,
    channels: Object.fromEntries(
      [...recording.channels].map(([topic, c]) => [
        topic,
        { schema: c.schemaName, messages: c.messageCount },
      ]),
    ),
    ...(loss?.['dropped'] !== undefined ? { dropped: Number(loss['dropped']) } : {}),
    ...(robot !== undefined ? { robot } : {}),
    ...(spaces.length > 0 ? { robots } : {}),
  };
}
