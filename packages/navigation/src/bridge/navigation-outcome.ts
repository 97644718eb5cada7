import type { HALToolResult } from '@hal/types';
import type { Point, Pose2D } from '../grid/geometry.js';

/** How a run ended. */
export type NavigationStatus = 'reached' | 'stopped' | 'failed';

/** Why a run ended. */
export type NavigationOutcomeReason =
  /** reached: the robot is within the goal tolerance. */
  | 'GOAL_REACHED'
  /** reached: an exploration run (no goal) whose provider said it is done. */
  | 'EXPLORATION_COMPLETE'
  /** stopped: `stop()` was called or the run's AbortSignal aborted. */
  | 'STOP_REQUESTED'
  /** stopped: the provider chose STOP away from the goal. */
  | 'PROVIDER_STOPPED'
  /** failed: the robot hit something (HAL code COLLISION). */
  | 'COLLISION'
  /** failed: the emergency stop is latched. */
  | 'EMERGENCY_STOPPED'
  /** failed: the cycle cap was reached. */
  | 'MAX_CYCLES'
  /** failed: the run's time cap was reached. */
  | 'TIME_LIMIT'
  /** failed: no route to the target for several cycles in a row, recovery included. */
  | 'UNREACHABLE'
  /** failed: the robot did not move for several motion commands, recovery included. */
  | 'STUCK'
  /** failed: a HAL call did not finish in time (the HAL's own TIMEOUT, or the bridge's). */
  | 'TIMEOUT'
  /** failed: the HAL is not ready, lost its link, or kept failing. */
  | 'HAL_ERROR'
  /** failed: the provider gave no decision (error or time out). */
  | 'PROVIDER_ERROR'
  /** failed: the provider's decision broke the decision schema. */
  | 'INVALID_DECISION';

/** The result of {@link NavigationBridge.run}. */
export interface NavigationOutcome {
  status: NavigationStatus;
  reason: NavigationOutcomeReason;
  /** One sentence for people and logs. */
  message: string;
  goal: Point | null;
  /** Decision cycles run. */
  cycles: number;
  /** Wall-clock duration of the run, ms (the bridge's clock). */
  elapsedMs: number;
  /** Every pose read from the HAL: the start, then one after each action. */
  trajectory: Pose2D[];
  /** The last pose read, when there was one. */
  finalPose?: Pose2D;
  /** Distance from the final pose to the goal, metres. */
  distanceToGoalM?: number;
  /** The HAL result that ended the run, when one did. */
  lastResult?: HALToolResult;
}

/** What ends a run, before the outcome's figures are added. */
export interface Terminal {
  status: NavigationStatus;
  reason: NavigationOutcomeReason;
  message: string;
}

/** A failed run's terminal. */
export function failed(reason: NavigationOutcomeReason, message: string): Terminal {
  return { status: 'failed', reason, message };
}

/** The terminal of a run ended by `stop()` or its AbortSignal. */
export function stopRequested(): Terminal {
  return { status: 'stopped', reason: 'STOP_REQUESTED', message: 'the run was stopped' };
}
