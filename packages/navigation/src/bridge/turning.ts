import { normalizeAngle } from '@hal/types';

/** Radians per degree. */
export const DEG = Math.PI / 180;

/** The turn from heading `yaw` to heading `target` (radians) the shorter way, degrees, left positive. */
export function turnDeg(yaw: number, target: number): number {
  return normalizeAngle(target - yaw) / DEG;
}

/** The `rotate` arguments for a turn of `deg` degrees, left positive. */
export function rotateArgs(deg: number): { direction: 'left' | 'right'; degrees: number } {
  return { direction: deg > 0 ? 'left' : 'right', degrees: Math.abs(deg) };
}
