// The live view's topics: the recorder's topic names and schemas (a live session and its
// recording look the same in Foxglove), advertised as JSON channels.
import {
  COMPRESSED_IMAGE,
  FRAME_TRANSFORM,
  HAL_POSE,
  LINK_STATS,
  LOG,
  POSE_IN_FRAME,
  SAFETY_EVENT,
  WHEEL_STEPS,
  robotNamespace,
} from '@hal/recorder';
import type { NamedJsonSchema, RobotNamespace } from '@hal/recorder';

/** The topics the view publishes, by what they carry. */
export type LiveTopic = 'pose' | 'halPose' | 'tf' | 'camera' | 'log' | 'safety' | 'steps' | 'link';

/** Each topic's schema (the recorder's). */
export const LIVE_SCHEMAS: Readonly<Record<LiveTopic, NamedJsonSchema>> = Object.freeze({
  pose: POSE_IN_FRAME,
  halPose: HAL_POSE,
  tf: FRAME_TRANSFORM,
  camera: COMPRESSED_IMAGE,
  log: LOG,
  safety: SAFETY_EVENT,
  steps: WHEEL_STEPS,
  link: LINK_STATS,
});

/** Where a viewer publishes teleop (geometry_msgs/Twist as JSON), and the services' names. */
export interface ControlNames {
  teleop: string;
  stop: string;
  emergencyStop: string;
  resetEmergencyStop: string;
}

/** The topic names and frames of a robot, under `/<namespace>` when it has one. */
export function liveNames(namespace?: string): {
  space: RobotNamespace;
  topics: Record<LiveTopic, string>;
  control: ControlNames;
} {
  const space = robotNamespace(namespace);
  const t = space.topics;
  const prefix = namespace === undefined ? '' : `/${namespace}`;
  return {
    space,
    topics: {
      pose: t.pose,
      halPose: t.halPose,
      tf: t.tf,
      camera: t.camera,
      log: t.log,
      safety: t.safety,
      steps: t.steps,
      link: t.link,
    },
    control: {
      teleop: `${prefix}/cmd_vel`,
      stop: `${prefix}/hal/stop`,
      emergencyStop: `${prefix}/hal/emergency_stop`,
      resetEmergencyStop: `${prefix}/hal/reset_emergency_stop`,
    },
  };
}

/** A Foxglove time from ms since the epoch. */
export function foxgloveTimeOfMs(ms: number): { sec: number; nsec: number } {
  const sec = Math.floor(ms / 1000);
  return { sec, nsec: Math.min(999_999_999, Math.round((ms - sec * 1000) * 1e6)) };
}
