// What `hal status` reports about a robot: identity, capabilities, pose, safety and health, read
// through the HAL interface only, so every kind of target answers the same way.
import type { HardwareAbstractionLayer, Pose } from '@hal/types';
import { poseText } from '../pose-text.js';

export interface StatusSnapshot {
  device: { id: string; type: string; mode: string };
  capabilities: string[];
  pose: Pose;
  safety: { emergencyStopped: boolean; reason?: string };
  health: { ready: boolean; batteryLevel: number; temperature?: number; errors: string[] };
  /** When this was read, ms since the epoch. */
  ts: number;
}

/** Reads a snapshot (the pose is the only call that may go to the robot). */
export async function readStatus(
  hal: HardwareAbstractionLayer,
  deviceId = hal.getDeviceInfo().id,
): Promise<StatusSnapshot> {
  const pose = await hal.locomotion.getPose();
  const info = hal.getDeviceInfo();
  const safety = hal.safety.getSafetyStatus();
  return {
    device: { id: deviceId, type: info.type, mode: info.mode },
    capabilities: [...info.capabilities],
    pose,
    safety: {
      emergencyStopped: hal.safety.isEmergencyStopped(),
      ...(safety.emergencyStopReason === undefined ? {} : { reason: safety.emergencyStopReason }),
    },
    health: {
      ready: hal.isReady(),
      batteryLevel: safety.batteryLevel,
      ...(safety.temperature === undefined ? {} : { temperature: safety.temperature }),
      errors: [...safety.errors],
    },
    ts: Date.now(),
  };
}

function safetyText(s: StatusSnapshot): string {
  if (!s.safety.emergencyStopped) return 'ok';
  return `EMERGENCY STOP${s.safety.reason === undefined ? '' : ` (${s.safety.reason})`}`;
}

function healthText(s: StatusSnapshot): string {
  const h = s.health;
  const parts = [
    h.ready ? 'ready' : 'NOT READY',
    `battery ${h.batteryLevel}%`,
    ...(h.temperature === undefined ? [] : [`${h.temperature.toFixed(1)} °C`]),
    h.errors.length === 0 ? 'no errors' : `errors: ${h.errors.join('; ')}`,
  ];
  return parts.join(', ');
}

/** The full report, one field a line. */
export function statusText(s: StatusSnapshot): string {
  return [
    `device        ${s.device.id} (${s.device.mode}, ${s.device.type})`,
    `capabilities  ${s.capabilities.length === 0 ? '(none)' : s.capabilities.join(' ')}`,
    `pose          ${poseText(s.pose, true)}`,
    `safety        ${safetyText(s)}`,
    `health        ${healthText(s)}`,
  ].join('\n');
}

/** One line per update for `--watch`. */
export function statusLine(s: StatusSnapshot): string {
  const time = new Date(s.ts).toISOString().slice(11, 23);
  return `${time}  ${poseText(s.pose, true)}  safety ${safetyText(s)}  ${s.health.ready ? 'ready' : 'NOT READY'}`;
}
