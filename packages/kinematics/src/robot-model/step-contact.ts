import type { PlanarPoseCm } from '../odometry.js';

/**
 * What the robot touched, as its owner describes it: at least the contact point, metres (a world
 * adds what was touched).
 */
export interface StepContact {
  point: { x: number; y: number };
}

/** Tells the robot whether a disc at (x, y) of radius r, metres, touches anything. */
export type ContactTest<C extends StepContact = StepContact> = (
  x: number,
  y: number,
  radius: number,
) => C | undefined;

/**
 * The contact that stops a robot of footprint `radius` going from pose `from` to pose `to`, or
 * undefined. Moving away from (or along) something already touched is allowed: only a motion
 * that brings the centre closer to the contact point is a collision.
 */
export function blockingContact<C extends StepContact>(
  test: ContactTest<C>,
  radius: number,
  from: PlanarPoseCm,
  to: PlanarPoseCm,
): C | undefined {
  const x = to.xCm / 100;
  const y = to.yCm / 100;
  const contact = test(x, y, radius);
  if (contact === undefined) return undefined;
  const before = Math.hypot(from.xCm / 100 - contact.point.x, from.yCm / 100 - contact.point.y);
  const after = Math.hypot(x - contact.point.x, y - contact.point.y);
  return after < before - 1e-12 ? contact : undefined;
}

/** How much room a robot has, as its owner measures it from one pose at one instant. */
export interface FreeSpace {
  /** How far the centre can move, metres, and touch no solid (<= 0: it may touch one now). */
  distance: number;
  /** Until when, µs, no other robot can touch it, whatever either does (Infinity: none can). */
  untilUs: number;
}

/** Measures the room of a disc of radius r at (x, y), metres, at `nowUs`. */
export type FreeSpaceTest = (x: number, y: number, radius: number, nowUs: number) => FreeSpace;

/** Room everywhere, always: a robot alone, with nothing to touch, takes every step unchecked. */
export const NOTHING_TO_TOUCH: FreeSpaceTest = () => ({
  distance: Number.POSITIVE_INFINITY,
  untilUs: Number.POSITIVE_INFINITY,
});
