import type { PlanarPoseCm } from '@hal/kinematics';
import type { Point, Solid } from '../shapes.js';

/** Where the robot touched something. */
export interface Contact {
  /** The contact point, metres, world frame. */
  point: Point;
  /** What was touched. */
  role: Solid['role'];
  /** Which one of its kind (map wall/obstacle index, robot index). */
  index: number;
  /** The robot's id, when another robot was touched. */
  robotId?: string;
}

/** Tells the robot whether a disc at (x, y) of radius r, metres, touches anything. */
export type ContactTest = (x: number, y: number, radius: number) => Contact | undefined;

/**
 * The contact that stops a robot of footprint `radius` going from pose `from` to pose `to`, or
 * undefined. Moving away from (or along) something already touched is allowed: only a motion
 * that brings the centre closer to the contact point is a collision.
 */
export function blockingContact(
  test: ContactTest,
  radius: number,
  from: PlanarPoseCm,
  to: PlanarPoseCm,
): Contact | undefined {
  const x = to.xCm / 100;
  const y = to.yCm / 100;
  const contact = test(x, y, radius);
  if (contact === undefined) return undefined;
  const before = Math.hypot(from.xCm / 100 - contact.point.x, from.yCm / 100 - contact.point.y);
  const after = Math.hypot(x - contact.point.x, y - contact.point.y);
  return after < before - 1e-12 ? contact : undefined;
}

/** How much room a robot has, as the world measures it from one pose at one instant. */
export interface FreeSpace {
  /** How far the centre can move, metres, and touch no solid (<= 0: it may touch one now). */
  distance: number;
  /** Until when, µs, no other robot can touch it, whatever either does (Infinity: none can). */
  untilUs: number;
}

/** Measures the room of a disc of radius r at (x, y), metres, at `nowUs`. */
export type FreeSpaceTest = (x: number, y: number, radius: number, nowUs: number) => FreeSpace;
