import type {
  MotionHandle as ModelMotionHandle,
  MotionReport as ModelMotionReport,
} from '@hal/kinematics';
import type { Contact } from './contact.js';

export type { MoveOutcome, SafetyTrip } from '@hal/kinematics';

/** One motion of a simulated robot, from its start to its end (a collision names its contact). */
export type MotionReport = ModelMotionReport<Contact>;

/** A started motion of a simulated robot: its report so far and a promise of its end. */
export type MotionHandle = ModelMotionHandle<Contact>;
