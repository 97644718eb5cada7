import type { RobotModel } from '@hal/kinematics';
import { HalError } from '@hal/types';
import type { LedState, MoveOutcome } from '../protocol/schemas.js';
import type { RobotClock } from './robot-clock.js';

/** Everything the mock robot's command handlers read and change. */
export interface RobotState {
  readonly clock: RobotClock;
  /** The firmware's rules: motion, odometry, e-stop, step limit, host timeout, configuration. */
  model: RobotModel;
  led: LedState;
}

/** The last motion's outcome as the wire says it ('none' before the first). */
export function moveOutcome(model: RobotModel): MoveOutcome {
  const outcome = model.motion?.outcome ?? 'none';
  // a collision needs a world to touch; the mock robot has none, so its model never reports one
  if (outcome === 'collision') {
    throw new HalError('HARDWARE_ERROR', 'the mock robot has nothing to collide with');
  }
  return outcome;
}

/** What a `stop` or `estop` reply reports (protocol 1.1): the motion it ended, and when. */
export function stopReport(state: RobotState): {
  move_id: number;
  move_outcome: string;
  move_left_steps: number;
  move_right_steps: number;
  left_steps: number;
  right_steps: number;
  uptime_us: number;
  stopped_us: number;
} {
  const { model } = state;
  const motion = model.motion;
  return {
    move_id: motion?.moveId ?? 0,
    move_outcome: moveOutcome(model),
    move_left_steps: motion?.doneLeft ?? 0,
    move_right_steps: motion?.doneRight ?? 0,
    left_steps: model.leftSteps,
    right_steps: model.rightSteps,
    uptime_us: state.clock.us(),
    // when the wheels last came to rest: the end of the last motion (0: never moved)
    stopped_us: motion?.endedUs ?? 0,
  };
}
