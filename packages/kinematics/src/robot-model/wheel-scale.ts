/*
 * How a robot's body may differ from the robot its firmware believes it is. The robot model only
 * applies the factors it is given for each motion; where they come from (the simulator's seeded
 * body error) is the simulator's business.
 */

/** Per-wheel factors on the nominal travel of a step (1: as the firmware believes). */
export interface WheelScale {
  left: number;
  right: number;
}

/** What one motion's steps do on the ground (`truth`) and in the odometry (`reported`). */
export interface MotionScales {
  truth: WheelScale;
  reported: WheelScale;
}

/** A source of per-motion scales (the simulator's `BodyErrorModel`). */
export interface BodyScales {
  nextMotion(): MotionScales;
}
