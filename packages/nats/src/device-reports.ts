// What a served device reports of itself on the spec's subjects: its health, a camera frame and
// its capability announcement, read from its HAL as each is asked for.
import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { getHeapStatistics } from 'node:v8';
import { jpegSize } from './jpeg-size.js';
import type { CameraFrame, CapabilityAnnouncement, Health } from './messages.js';

/** What the gateway knows of itself that the HAL does not: how long it has run, its CPU use. */
export interface HealthContext {
  uptimeS: number;
  cpuPercent: number;
  /** The request's `include_diagnostics`: the HAL's errors (and the battery voltage) beside. */
  includeDiagnostics: boolean;
}

/** The `health` reply: not ready, e-stopped, degraded (errors reported) or healthy. */
export function healthOf(hal: HardwareAbstractionLayer, context: HealthContext): Health {
  const status = hal.safety.getSafetyStatus();
  const health: Health = {
    status: !hal.isReady()
      ? 'not_ready'
      : status.emergencyStopped
        ? 'emergency_stopped'
        : status.errors.length > 0
          ? 'degraded'
          : 'healthy',
    uptime_s: context.uptimeS,
    mode: hal.mode,
    free_memory_bytes: getHeapStatistics().total_available_size,
    cpu_percent: context.cpuPercent,
    battery_percent: status.batteryLevel,
  };
  if (status.temperature !== undefined) health.temperature_celsius = status.temperature;
  if (context.includeDiagnostics) {
    health.diagnostics = { errors: status.errors };
    if (status.batteryVoltage !== undefined) health.diagnostics.voltage = status.batteryVoltage;
  }
  return health;
}

/**
 * The `camera.frame` reply: the HAL's frame as base64 JPEG with its size read from the JPEG
 * itself; a frame that is not a JPEG is a HARDWARE_ERROR.
 */
export async function cameraFrameOf(hal: HardwareAbstractionLayer): Promise<CameraFrame> {
  const url = await hal.vision.captureFrame();
  const data = url.slice(url.indexOf(',') + 1);
  const size = jpegSize(Buffer.from(data, 'base64'));
  if (size === undefined) {
    throw new HalError('HARDWARE_ERROR', 'the camera returned a frame that is not a JPEG');
  }
  return { format: 'jpeg', width: size.width, height: size.height, data, timestamp_ms: Date.now() };
}

/** The capability announcement: the device's type, mode, capabilities and state rate. */
export function announcementOf(
  hal: HardwareAbstractionLayer,
  stateRateHz: number,
): CapabilityAnnouncement {
  const info = hal.getDeviceInfo();
  return {
    device_type: info.type,
    mode: info.mode,
    caps: info.capabilities,
    state_rate_hz: stateRateHz,
  };
}
