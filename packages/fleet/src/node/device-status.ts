import type { PlanarPose } from '@hal/types';
import type { DeviceConfig } from './device-config.js';

/** One telemetry reading of a device. */
export interface DeviceTelemetry {
  device: string;
  /** When it was read, ms since the Unix epoch. */
  at: number;
  pose: PlanarPose;
  /** Linear and angular velocity, m/s and rad/s. */
  velocity: { linear: number; angular: number };
  emergencyStopped: boolean;
  batteryLevel?: number;
  errors: string[];
}

/** A device's health as the manager sees it. */
export interface DeviceHealth {
  device: string;
  type: DeviceConfig['type'];
  /** Answered a read within `offlineAfterMs`. */
  online: boolean;
  /** Its HAL reports ready. */
  ready: boolean;
  emergencyStopped: boolean;
  /** When it last answered, ms since the Unix epoch (absent: never). */
  lastSeen?: number;
  /** The last telemetry reading, if any. */
  telemetry?: DeviceTelemetry;
  /** Why the last read or connection attempt failed. */
  lastError?: string;
}

/** What the device manager reports to listeners. */
export interface DeviceManagerEvents {
  online: { device: string };
  offline: { device: string; reason: string };
  telemetry: DeviceTelemetry;
}
