import type { Pose } from '@hal/types';
import {
  COMPRESSED_IMAGE,
  FOXGLOVE_LOG_LEVEL,
  FRAME_TRANSFORM,
  LOG,
  POSE_IN_FRAME,
  foxgloveTime,
  quaternionFromEuler,
} from './foxglove-schemas.js';
import { jsonSafe } from './json-safe.js';
import { CALL_RECORD, HAL_POSE, LINK_STATS, SAFETY_EVENT, WHEEL_STEPS } from './messages.js';
import type { HalCallRecord, LinkStats, SafetyEvent, WheelSteps } from './messages.js';
import type { RobotNamespace } from './namespace.js';
import type { McapRecorder } from './recorder.js';

/** What one robot's recording writes, each on its topic with its schema (docs/recording.md). */
export interface RobotTopicWriter {
  /** A call's record (`/hal/calls`). */
  call(entry: HalCallRecord, at: bigint): void;
  /** The pose as asked for at `at` (the robot may have moved on since): `/hal/pose`, `/tf`, `/hal/pose/raw`. */
  pose(pose: Pose, at: bigint): void;
  /** The wheel counters the robot reported (`/hal/steps`), read at `at` or now. */
  steps(steps: WheelSteps, at?: bigint): void;
  /** The link's statistics (`/hal/link`). */
  link(link: LinkStats): void;
  /** An e-stop, a reset or a trip (`/hal/safety`), at `at` or now. */
  safety(event: SafetyEvent, at?: bigint): void;
  /** A camera frame, a data URL as `captureFrame` answers (`/hal/camera`). */
  camera(dataUrl: string, at: bigint): void;
  /** A log line as `communication.log` takes it, from the robot `name` (`/hal/log`). */
  log(message: unknown, level: unknown, name: string, at: bigint): void;
  /** The robot's metadata record (`hal.robot`). */
  robot(values: Record<string, string>): void;
}

/**
 * Declares one robot's channels in `recorder` (the steps and link topics only for a robot that
 * reports them) and hands back what writes its messages, in the Foxglove schemas where one fits.
 */
export function robotTopicWriter(
  recorder: McapRecorder,
  space: RobotNamespace,
  reports: { steps: boolean; link: boolean },
): RobotTopicWriter {
  const { topics } = space;
  for (const [topic, schema] of [
    [topics.calls, CALL_RECORD],
    [topics.pose, POSE_IN_FRAME],
    [topics.halPose, HAL_POSE],
    [topics.tf, FRAME_TRANSFORM],
    [topics.camera, COMPRESSED_IMAGE],
    [topics.log, LOG],
    [topics.safety, SAFETY_EVENT],
  ] as const) {
    recorder.channel(topic, schema);
  }
  if (reports.steps) recorder.channel(topics.steps, WHEEL_STEPS);
  if (reports.link) recorder.channel(topics.link, LINK_STATS);
  const baseLink = space.frame('base_link');
  const cameraFrame = space.frame('camera');

  return {
    call: (entry, at) => recorder.write(topics.calls, entry, at),
    pose(pose, at) {
      const timestamp = foxgloveTime(at);
      const { x, y, z } = pose.position;
      const { yaw, pitch, roll } = pose.rotation;
      const orientation = quaternionFromEuler(yaw, pitch, roll);
      recorder.write(
        topics.pose,
        { timestamp, frame_id: 'world', pose: { position: { x, y, z }, orientation } },
        at,
      );
      recorder.write(
        topics.tf,
        {
          timestamp,
          parent_frame_id: 'world',
          child_frame_id: baseLink,
          translation: { x, y, z },
          rotation: orientation,
        },
        at,
      );
      recorder.write(topics.halPose, jsonSafe(pose), at);
    },
    steps: (steps, at) => recorder.write(topics.steps, steps, at),
    link: (link) => recorder.write(topics.link, link),
    safety: (event, at) => recorder.write(topics.safety, event, at),
    camera(dataUrl, at) {
      const comma = dataUrl.indexOf(',');
      const format = /^data:image\/(\w+)/.exec(dataUrl)?.[1] ?? 'jpeg';
      recorder.write(
        topics.camera,
        {
          timestamp: foxgloveTime(at),
          frame_id: cameraFrame,
          data: comma >= 0 ? dataUrl.slice(comma + 1) : dataUrl,
          format,
        },
        at,
      );
    },
    log(message, level, name, at) {
      recorder.write(
        topics.log,
        {
          timestamp: foxgloveTime(at),
          level: FOXGLOVE_LOG_LEVEL[level as keyof typeof FOXGLOVE_LOG_LEVEL] ?? 2,
          message: String(message),
          name,
          file: '',
          line: 0,
        },
        at,
      );
    },
    robot: (values) => recorder.metadata(space.metadataName, values),
  };
}
