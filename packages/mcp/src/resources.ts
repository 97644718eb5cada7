import type { HardwareAbstractionLayer } from '@hal/types';
import { hasCapability, CAPABILITIES } from '@hal/types';
import { robotConfigOf } from '@hal/tools';
import type { AgentTool } from '@hal/tools';
import type { RobotEvents } from './events.js';

/** One resource the server lists, and how to read it. */
export interface RobotResource {
  uri: string;
  name: string;
  description: string;
  mimeType: 'application/json' | 'image/jpeg';
  read: () => Promise<{ text: string } | { blob: string }>;
}

/** What the server knows of the world the robot is in. */
export interface RobotWorld {
  /** The map of the arena (the simulator's), as JSON; absent for a robot with no map. */
  map?: () => unknown;
}

/** The robot's state, and its events: the resources a client can subscribe to. */
export const STATE_URI = 'robot://state';
export const EVENTS_URI = 'robot://events';

const json = (value: unknown) => ({ text: JSON.stringify(value, null, 2) });

/** What robot://state holds: readiness, mode, pose and safety status. */
export async function stateOf(hal: HardwareAbstractionLayer) {
  return {
    ready: hal.isReady(),
    mode: hal.mode,
    pose: hal.isReady() ? await hal.locomotion.getPose() : null,
    safety: hal.safety.getSafetyStatus(),
  };
}

/**
 * The robot's resources: its state (pose, safety, readiness), what it can do (device info,
 * limits, tools) and the map of its world, and the camera's latest frame where it has one.
 */
export function robotResources(
  hal: HardwareAbstractionLayer,
  tools: readonly AgentTool[],
  world: RobotWorld = {},
  events?: RobotEvents,
): RobotResource[] {
  const resources: RobotResource[] = [
    {
      uri: STATE_URI,
      name: 'state',
      description:
        'Pose (REP-103: metres, radians, m/s, rad/s), safety status (e-stop, battery, faults) and readiness',
      mimeType: 'application/json',
      read: async () => json(await stateOf(hal)),
    },
    {
      uri: 'robot://capabilities',
      name: 'capabilities',
      description:
        'Who the robot is, its capability strings, its limits and the tools it is offered',
      mimeType: 'application/json',
      read: async () =>
        json({
          device: hal.getDeviceInfo(),
          limits: robotConfigOf(hal),
          tools: tools.map((t) => t.name),
        }),
    },
    {
      uri: 'robot://map',
      name: 'map',
      description:
        world.map === undefined
          ? 'No map: this robot has none (it reports no occupancy grid or arena)'
          : 'The arena (REP-103 world frame, metres): its size, walls, obstacles and start poses',
      mimeType: 'application/json',
      read: async () =>
        json(
          world.map === undefined
            ? {
                map: null,
                why: 'this robot has no map; scan or read the range sensors to see around it',
              }
            : { map: world.map() },
        ),
    },
  ];
  if (events !== undefined) {
    resources.push({
      uri: EVENTS_URI,
      name: 'events',
      description:
        'Recent events, oldest first: e-stops (by whom, why), resets, collisions, guard stops, ' +
        'the link lost and back, low battery, faults; subscribe to be told of new ones',
      mimeType: 'application/json',
      read: async () => json({ events: events.recent() }),
    });
  }
  if (hasCapability(hal.getDeviceInfo().capabilities, CAPABILITIES.camera)) {
    resources.push({
      uri: 'robot://camera',
      name: 'camera',
      description: "The camera's latest frame, a JPEG",
      mimeType: 'image/jpeg',
      read: async () => ({ blob: (await hal.vision.captureFrame()).replace(/^data:[^,]*,/, '') }),
    });
  }
  return resources;
}
