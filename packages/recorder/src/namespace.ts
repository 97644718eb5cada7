import { HalError } from '@hal/types';
import { TOPICS } from './messages.js';

/** The topics of one robot in a recording. */
export interface RobotTopics {
  calls: string;
  pose: string;
  halPose: string;
  tf: string;
  camera: string;
  log: string;
  safety: string;
  steps: string;
  link: string;
}

/** Where one robot's messages go: its topics, its frames and its metadata record. */
export interface RobotNamespace {
  /** The namespace itself (undefined for a recording of one robot). */
  namespace: string | undefined;
  topics: RobotTopics;
  /** The robot's frame `name` (`base_link`, `camera`): `sim-1/base_link` in a namespace. */
  frame(name: string): string;
  /** The name of its metadata record: `hal.robot`, or `hal.robot/sim-1` in a namespace. */
  metadataName: string;
}

/** A namespace as a device id is written: letters, digits, `-` and `_`. */
const NAMESPACE = /^[A-Za-z0-9_-]{1,64}$/;

/**
 * The topics, frames and metadata name of a robot: as `TOPICS` has them when `namespace` is
 * undefined, else under `/<namespace>` (the ROS convention for several robots in one bag), its
 * frames prefixed `<namespace>/` under the shared `world`. INVALID_PARAMETER for a namespace that
 * is not 1-64 letters, digits, `-` or `_`.
 */
export function robotNamespace(namespace?: string): RobotNamespace {
  if (namespace !== undefined && !NAMESPACE.test(namespace)) {
    throw new HalError(
      'INVALID_PARAMETER',
      `"namespace" must be 1-64 letters, digits, '-' or '_', got ${JSON.stringify(namespace)}`,
      { details: { parameter: 'namespace' } },
    );
  }
  const prefix = namespace === undefined ? '' : `/${namespace}`;
  const { calls, pose, halPose, tf, camera, log, safety, steps, link } = TOPICS;
  const own = { calls, pose, halPose, tf, camera, log, safety, steps, link };
  return {
    namespace,
    topics: Object.fromEntries(
      Object.entries(own).map(([key, topic]) => [key, `${prefix}${topic}`]),
    ) as unknown as RobotTopics,
    frame: (name) => (namespace === undefined ? name : `${namespace}/${name}`),
    metadataName: namespace === undefined ? 'hal.robot' : `hal.robot/${namespace}`,
  };
}

/** The namespace of a robot's call topic (`/sim-1/hal/calls` -> `sim-1`; `/hal/calls` -> ''). */
export function namespaceOfCallTopic(topic: string): string | undefined {
  if (topic === TOPICS.calls) return '';
  const match = /^\/([A-Za-z0-9_-]{1,64})\/hal\/calls$/.exec(topic);
  return match?.[1];
}
