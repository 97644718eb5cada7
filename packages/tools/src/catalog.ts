import { CAPABILITIES } from '@hal/types';
import type { CallName } from '@hal/types';

/** How a tool is gated: a stop is never blocked by the leash, approval or the rate limit. */
export type ToolSafety = 'stop' | 'estop';

/** One entry of the catalog: which HAL call a tool runs and what the robot must offer for it. */
export interface ToolEntry {
  name: string;
  call: CallName;
  /** A capability string the robot must offer; absent: every robot has the call. */
  requires?: string;
  motion: boolean;
  safety?: ToolSafety;
  /** What the tool does, ahead of the schema's own description (units, limits). */
  summary: string;
}

const DRIVE = CAPABILITIES.differentialDrive;

/**
 * Every HAL call as a tool, in the order tools are listed. The names are stable: agents and
 * transcripts refer to them. Units, frame and limits come from the call schemas' descriptions.
 */
export const TOOL_CATALOG: readonly ToolEntry[] = Object.freeze([
  {
    name: 'move_forward',
    call: 'moveForward',
    requires: DRIVE,
    motion: true,
    summary: 'Drive straight ahead (REP-103: +x of the robot) and stop; returns when done.',
  },
  {
    name: 'move_backward',
    call: 'moveBackward',
    requires: DRIVE,
    motion: true,
    summary: 'Drive straight back (-x of the robot) and stop; returns when done.',
  },
  {
    name: 'rotate',
    call: 'rotate',
    requires: DRIVE,
    motion: true,
    summary: 'Turn in place; left is counter-clockwise (REP-103 yaw increases). Returns when done.',
  },
  {
    name: 'move_to',
    call: 'moveTo',
    requires: DRIVE,
    motion: true,
    summary:
      'Drive to a point of the world frame (REP-103: metres, x forward, y left of the start ' +
      'pose): turns toward it in place, then drives straight. Returns on arrival.',
  },
  {
    name: 'drive',
    call: 'drive',
    requires: DRIVE,
    motion: true,
    summary:
      'Set the wheel powers directly (equal powers: straight; opposite: turn in place). Give ' +
      'durationMs, or the wheels keep turning until stop.',
  },
  {
    name: 'stop',
    call: 'stop',
    motion: false,
    safety: 'stop',
    summary: 'Stop the wheels now. Always allowed.',
  },
  {
    name: 'emergency_stop',
    call: 'emergencyStop',
    motion: false,
    safety: 'estop',
    summary:
      'Emergency stop: stops everything and latches; motion is refused until ' +
      'reset_emergency_stop. Always allowed, whatever the reason given.',
  },
  {
    name: 'reset_emergency_stop',
    call: 'resetEmergencyStop',
    motion: false,
    summary: 'Clear a latched emergency stop so the robot may move again.',
  },
  { name: 'get_pose', call: 'getPose', motion: false, summary: 'Where the robot is.' },
  {
    name: 'capture_frame',
    call: 'captureFrame',
    requires: CAPABILITIES.camera,
    motion: false,
    summary: 'Look through the camera: returns the latest frame as a JPEG image.',
  },
  {
    name: 'get_distance_sensors',
    call: 'getDistanceSensors',
    requires: CAPABILITIES.rangeSensors,
    motion: false,
    summary: 'How far the nearest obstacles are.',
  },
  {
    name: 'scan',
    call: 'scan',
    requires: CAPABILITIES.rangeSensors,
    motion: false,
    summary: 'Look around for obstacles.',
  },
  {
    name: 'get_line_sensors',
    call: 'getLineSensors',
    requires: CAPABILITIES.lineSensors,
    motion: false,
    summary: 'Read the floor line sensors.',
  },
  { name: 'get_imu', call: 'getIMU', motion: false, summary: 'Read the inertial sensors.' },
  {
    name: 'get_safety_status',
    call: 'getSafetyStatus',
    motion: false,
    summary: 'Read the safety state.',
  },
  {
    name: 'is_emergency_stopped',
    call: 'isEmergencyStopped',
    motion: false,
    summary: 'Whether the emergency stop is latched.',
  },
  {
    name: 'set_led',
    call: 'setLED',
    requires: CAPABILITIES.led,
    motion: false,
    summary: 'Set the status LED colour and pattern.',
  },
  {
    name: 'speak',
    call: 'speak',
    requires: CAPABILITIES.speaker,
    motion: false,
    summary: 'Say something aloud.',
  },
  {
    name: 'play_sound',
    call: 'playSound',
    requires: CAPABILITIES.sound,
    motion: false,
    summary: 'Play a sound effect.',
  },
  { name: 'log', call: 'log', motion: false, summary: 'Write a message to the robot log.' },
]);
