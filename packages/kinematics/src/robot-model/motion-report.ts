import type { StepContact } from './step-contact.js';

/** How a motion ended (the firmware's `move_outcome`, plus `collision`, which only a world has). */
export type MoveOutcome =
  'running' | 'done' | 'stopped' | 'estop' | 'host_timeout' | 'replaced' | 'collision';

/** One motion, from its start to its end. */
export interface MotionReport<C extends StepContact = StepContact> {
  /** Increases by one per motion command. */
  moveId: number;
  /** `move` for move_steps/move_cm/rotate_deg, `drive` for velocity mode. */
  kind: 'move' | 'drive';
  /** Signed steps the motion plans per wheel (moves only). */
  plannedLeft: number;
  plannedRight: number;
  /** Signed wheel speeds, steps/s (drives only). */
  leftSps: number;
  rightSps: number;
  /** The master wheel's cruise speed, steps/s, after clamping. */
  speed: number;
  speedClamped: boolean;
  /** Planned duration, µs (a drive: its duration limit, or Infinity). */
  durationUs: number;
  /** Steps executed so far by this motion. */
  doneLeft: number;
  doneRight: number;
  /** Simulated time the motion started and (once over) ended, µs. */
  startedUs: number;
  endedUs: number | undefined;
  outcome: MoveOutcome;
  /** Set when the outcome is `collision`. */
  contact?: C;
}

/** A started motion: its report so far and a promise of its end. */
export interface MotionHandle<C extends StepContact = StepContact> {
  report: MotionReport<C>;
  finished: Promise<MotionReport<C>>;
}
