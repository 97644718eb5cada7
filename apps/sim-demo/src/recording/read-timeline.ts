import { readRecording, RecordingReadError, TOPICS } from '@hal/recorder';
import type { RecordedMessage, Recording } from '@hal/recorder';
import { PoseSchema } from '@hal/types';
import { RecordingFileError } from './recording-file-error.js';
import type { PlaybackTimeline, TimedFrame, TimedPose } from './timeline.js';

/*
 * Reads an MCAP file into a time line with @hal/recorder's reader (@mcap/core). The demo loads
 * this module on the first file opened, so the page itself does not carry the MCAP reader.
 */

/** The topics the demo plays back: any of them makes a file playable. */
const ROBOT_TOPICS = [TOPICS.halPose, TOPICS.pose, TOPICS.camera] as const;

/** Yaw (REP-103, about z) of a unit quaternion. */
function yawOf(q: { x: number; y: number; z: number; w: number }): number {
  return Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

function finite(...values: unknown[]): boolean {
  return values.every((v) => typeof v === 'number' && Number.isFinite(v));
}

/** A pose from `/hal/pose/raw` (the HAL's Pose) or `/hal/pose` (foxglove.PoseInFrame). */
function planarPose(message: RecordedMessage): Omit<TimedPose, 't'> | undefined {
  if (message.topic === TOPICS.halPose) {
    const parsed = PoseSchema.safeParse(message.value);
    if (!parsed.success) return undefined;
    const { position, rotation } = parsed.data;
    return { x: position.x, y: position.y, yaw: rotation.yaw };
  }
  const pose = (message.value as { pose?: { position?: unknown; orientation?: unknown } } | null)
    ?.pose;
  const p = pose?.position as { x?: unknown; y?: unknown } | undefined;
  const q = pose?.orientation as { x?: unknown; y?: unknown; z?: unknown; w?: unknown } | undefined;
  if (!finite(p?.x, p?.y, q?.x, q?.y, q?.z, q?.w)) return undefined;
  const { x, y } = p as { x: number; y: number };
  return { x, y, yaw: yawOf(q as { x: number; y: number; z: number; w: number }) };
}

function cameraFrame(message: RecordedMessage): string | undefined {
  const { data, format } = (message.value ?? {}) as { data?: unknown; format?: unknown };
  if (typeof data !== 'string' || data.length === 0) return undefined;
  const type = typeof format === 'string' && /^\w+$/.test(format) ? format : 'jpeg';
  return `data:image/${type};base64,${data}`;
}

/** The time line of a recording already read. */
export function timelineOf(name: string, recording: Recording): PlaybackTimeline {
  const topics = ROBOT_TOPICS.filter((t) => (recording.channels.get(t)?.messageCount ?? 0) > 0);
  if (topics.length === 0) {
    const found = [...recording.channels.keys()].join(', ') || 'none';
    const cut = recording.truncation !== undefined ? ` (read up to: ${recording.truncation})` : '';
    throw new RecordingFileError(
      'NO_ROBOT_TOPICS',
      `${name} has none of the robot's topics (${ROBOT_TOPICS.join(', ')}); its topics: ${found}${cut}`,
    );
  }
  // The HAL's own pose when the file has it (its yaw as the robot reported it), else Foxglove's.
  const poseTopic = topics.includes(TOPICS.halPose) ? TOPICS.halPose : TOPICS.pose;
  const timed = recording.messages.filter(
    (m) => m.topic === poseTopic || m.topic === TOPICS.camera,
  );
  const start = timed[0]?.logTime ?? 0n;
  const at = (m: RecordedMessage): number => Number(m.logTime - start) / 1e6;
  const poses: TimedPose[] = [];
  const frames: TimedFrame[] = [];
  for (const message of timed) {
    if (message.topic === TOPICS.camera) {
      const src = cameraFrame(message);
      if (src !== undefined) frames.push({ t: at(message), src });
    } else {
      const pose = planarPose(message);
      if (pose !== undefined) poses.push({ t: at(message), ...pose });
    }
  }
  const last = timed[timed.length - 1];
  return {
    name,
    durationMs: last === undefined ? 0 : at(last),
    poses,
    frames,
    calls: recording.channels.get(TOPICS.calls)?.messageCount ?? 0,
    deviceId: recording.metadata.get('hal.robot')?.['device_id'] ?? '',
    ...(recording.truncation !== undefined ? { truncation: recording.truncation } : {}),
  };
}

/**
 * Reads the MCAP file `bytes` (named `name`) into a time line. Refuses, with a
 * {@link RecordingFileError}, what the recorder's reader refuses (a file that is empty, not
 * MCAP, without a header, or damaged with nothing readable: its code and reason), and a file
 * with none of the robot's topics. A file cut short or damaged in part is played as far as it
 * reads, and `truncation` says where reading stopped.
 */
export async function readTimeline(name: string, bytes: Uint8Array): Promise<PlaybackTimeline> {
  let recording;
  try {
    recording = await readRecording(bytes, { name });
  } catch (error) {
    if (error instanceof RecordingReadError) {
      throw new RecordingFileError(error.code, error.message);
    }
    throw error;
  }
  return timelineOf(name, recording);
}
