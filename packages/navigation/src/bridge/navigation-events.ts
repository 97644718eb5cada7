import type { HALToolResult } from '@hal/types';
import type { Point, Pose2D } from '../grid/geometry.js';
import type { RangeReadings } from '../grid/range-sensor-update.js';
import type { NavigationDecision } from '../decision/schema.js';
import type { PathPlan } from '../planner/grid-planner.js';
import type { NavigationOutcome } from './navigation-outcome.js';

/** The events a {@link NavigationBridge} emits, for UIs and logs. */
export interface NavigationEvents {
  /** A cycle starts: the pose just read and the range readings. */
  cycle: { cycle: number; pose: Pose2D; readings?: RangeReadings; elapsedMs: number };
  /** The provider decided. */
  decision: { cycle: number; provider: string; decision: NavigationDecision };
  /** A route was planned; `leg` is the point the robot drives to this cycle. */
  path: { cycle: number; target: Point; plan: PathPlan; leg: Point };
  /** A HAL call finished: `call` is its name in the HAL's call table. */
  result: {
    cycle: number;
    call: string;
    args: Record<string, unknown>;
    result: HALToolResult;
  };
  /** The run ended. */
  done: NavigationOutcome;
}
