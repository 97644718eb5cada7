import { HalError, toHalError } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import type { PlanarPose } from '@hal/types';
import type { FleetScheduler } from './scheduler.js';

/**
 * Reads a member's planar pose, or rejects with a HalError: the HAL's own, or TIMEOUT when no
 * pose comes within `timeoutMs` on the scheduler's clock.
 */
export function readPose(
  hal: HardwareAbstractionLayer,
  device: string,
  timeoutMs: number,
  scheduler: FleetScheduler,
): Promise<PlanarPose> {
  return new Promise<PlanarPose>((resolve, reject) => {
    let settled = false;
    const timer = scheduler.setTimeout(() => {
      if (settled) return;
      settled = true;
      reject(
        new HalError('TIMEOUT', `device "${device}" gave no pose within ${timeoutMs} ms`, {
          details: { device, timeoutMs },
        }),
      );
    }, timeoutMs);
    let pending: Promise<PlanarPose>;
    try {
      pending = hal.locomotion
        .getPose()
        .then((p) => ({ x: p.position.x, y: p.position.y, yaw: p.rotation.yaw }));
    } catch (thrown) {
      pending = Promise.reject(thrown);
    }
    pending.then(
      (pose) => {
        if (settled) return;
        settled = true;
        scheduler.clearTimeout(timer);
        resolve(pose);
      },
      (thrown: unknown) => {
        if (settled) return;
        settled = true;
        scheduler.clearTimeout(timer);
        reject(toHalError(thrown));
      },
    );
  });
}
