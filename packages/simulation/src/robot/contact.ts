import type { ContactTest as StepContactTest, FreeSpace, FreeSpaceTest } from '@hal/kinematics';
import type { Point, Solid } from '../shapes.js';

export { blockingContact } from '@hal/kinematics';
export type { FreeSpace, FreeSpaceTest };

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
export type ContactTest = StepContactTest<Contact>;
