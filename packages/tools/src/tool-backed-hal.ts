import { HAL_ERROR_CODES, HalError } from '@hal/types';
import type { HALToolResult, HalErrorCode, HardwareAbstractionLayer } from '@hal/types';
import type { ToolCall } from './executor.js';
import type { ToolResult } from './result.js';

const CODES = new Set<string>(HAL_ERROR_CODES);

/** A tool's answer as the HALToolResult a motion call resolves with (refusals included). */
function asHalResult(result: ToolResult, mode: HardwareAbstractionLayer['mode']): HALToolResult {
  const s = result.structured ?? {};
  if (typeof s['success'] === 'boolean') return s as unknown as HALToolResult;
  const code = typeof s['code'] === 'string' ? s['code'] : 'HARDWARE_ERROR';
  return {
    success: false,
    error: typeof s['error'] === 'string' ? s['error'] : code,
    // the executor's own codes (LEASH_DISTANCE, BUDGET_EXCEEDED...) are no HalErrorCode: they
    // travel in the details, so a controller can still tell a refusal from a fault
    ...(CODES.has(code) ? { code: code as HalErrorCode } : { details: { code } }),
    timestamp: 0,
    mode,
  };
}

/** A tool's answer as the value a read call resolves with; a refusal rejects as a HalError. */
function asValue<T>(result: ToolResult): T {
  if (!result.isError) return result.structured as T;
  const s = result.structured ?? {};
  const code =
    typeof s['code'] === 'string' && CODES.has(s['code'])
      ? (s['code'] as HalErrorCode)
      : 'HARDWARE_ERROR';
  throw new HalError(code, typeof s['error'] === 'string' ? s['error'] : code);
}

/**
 * `hal` with its motion and sensor calls sent through the trial's tools, so a controller that
 * drives a HAL (the navigation bridge) meets the same leash, faults and budget as a model and
 * its calls are counted the same way; so is a reset of the e-stop (the trial's log records it).
 * State that is read synchronously (the e-stop, readiness, device info) and the e-stop itself
 * come from `hal` itself.
 */
export function toolBackedHal(
  hal: HardwareAbstractionLayer,
  execute: (call: ToolCall) => Promise<ToolResult>,
): HardwareAbstractionLayer {
  const motion = async (name: string, args: Record<string, unknown>) =>
    asHalResult(await execute({ name, arguments: args }), hal.mode);
  const read = async <T>(name: string, args: Record<string, unknown> = {}) =>
    asValue<T>(await execute({ name, arguments: args }));
  const locomotion: HardwareAbstractionLayer['locomotion'] = {
    ...hal.locomotion,
    moveTo: (x, y, z, speed) =>
      motion('move_to', { x, y, z, ...(speed === undefined ? {} : { speed }) }),
    rotate: (direction, degrees) => motion('rotate', { direction, degrees }),
    moveForward: (distanceCm) => motion('move_forward', { distanceCm }),
    moveBackward: (distanceCm) => motion('move_backward', { distanceCm }),
    stop: () => motion('stop', {}),
    getPose: () => read('get_pose'),
  };
  const vision: HardwareAbstractionLayer['vision'] = {
    ...hal.vision,
    getDistanceSensors: () => read('get_distance_sensors'),
    captureFrame: async () => {
      const result = await execute({ name: 'capture_frame', arguments: {} });
      asValue(result);
      const image = result.content.find((c) => c.type === 'image');
      return image === undefined ? '' : `data:image/jpeg;base64,${image.data}`;
    },
  };
  // a reset goes through the tools, so the trial's log records it (the e-stop itself goes to the
  // robot directly: the budget must never refuse it)
  const safety = new Proxy(hal.safety, {
    get(target, key, receiver) {
      if (key === 'resetEmergencyStop') return () => motion('reset_emergency_stop', {});
      const value: unknown = Reflect.get(target, key, receiver);
      return typeof value === 'function'
        ? (value as (...a: unknown[]) => unknown).bind(target)
        : value;
    },
  });
  return new Proxy(hal, {
    get(target, key, receiver) {
      if (key === 'locomotion') return locomotion;
      if (key === 'safety') return safety;
      if (key === 'vision') return vision;
      const value: unknown = Reflect.get(target, key, receiver);
      return typeof value === 'function'
        ? (value as (...a: unknown[]) => unknown).bind(target)
        : value;
    },
  });
}
