// Runs one decoded call on the served HAL. Arguments are passed positionally, exactly as a local
// caller would pass them, so the HAL's own boundary validates them (and names the parameter).
import { HalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { REMOTE_CALLS } from '../protocol.js';
import type { RemoteCallName } from '../protocol.js';

type Target = (hal: HardwareAbstractionLayer) => object;

const TARGETS: Record<RemoteCallName, Target> = {
  drive: (h) => h.locomotion,
  moveTo: (h) => h.locomotion,
  rotate: (h) => h.locomotion,
  moveForward: (h) => h.locomotion,
  moveBackward: (h) => h.locomotion,
  stop: (h) => h.locomotion,
  getPose: (h) => h.locomotion,
  captureFrame: (h) => h.vision,
  scan: (h) => h.vision,
  getDistanceSensors: (h) => h.vision,
  getLineSensors: (h) => h.vision,
  getIMU: (h) => h.vision,
  speak: (h) => h.communication,
  setLED: (h) => h.communication,
  playSound: (h) => h.communication,
  log: (h) => h.communication,
  emergencyStop: (h) => h.safety,
  resetEmergencyStop: (h) => h.safety,
  getSafetyStatus: (h) => h.safety,
  isEmergencyStopped: (h) => h.safety,
};

/** True for a call name the server knows. */
export function isRemoteCall(name: string): name is RemoteCallName {
  return (REMOTE_CALLS as readonly string[]).includes(name);
}

/** Runs `call` on `hal` with `args`; a synchronous throw becomes a rejection. */
export async function dispatchCall(
  hal: HardwareAbstractionLayer,
  call: RemoteCallName,
  args: readonly unknown[],
): Promise<unknown> {
  const target = TARGETS[call](hal) as Record<string, unknown>;
  const method = target[call];
  if (typeof method !== 'function') {
    throw new HalError('NOT_IMPLEMENTED', `the served HAL has no "${call}"`);
  }
  const value: unknown = await (method as (...a: unknown[]) => unknown).apply(target, [...args]);
  return call === 'log' ? null : value;
}
