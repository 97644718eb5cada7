import type { Point, Pose2D } from '../grid/geometry.js';
import type { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { RangeReadings } from '../grid/range-sensor-update.js';
import type { NavigationDecision } from './schema.js';

/** What happened to the previous action, as the bridge saw it. */
export interface ActionReport {
  action: NavigationDecision['action']['type'];
  success: boolean;
  /** The HAL's or the planner's message when it failed. */
  error?: string;
  /** The HAL's error code, or a planner status such as `unreachable`. */
  code?: string;
}

/** Everything a decision provider may look at to choose the next action. */
export interface DecisionContext {
  /** 1 for the first decision of a run. */
  cycle: number;
  /** Where to go, metres; null for a pure exploration run. */
  goal: Point | null;
  /** How close to the goal counts as there, metres. */
  goalToleranceM: number;
  /** The robot's pose now (REP-103, metres, radians). */
  pose: Pose2D;
  /** The world model, up to date with this cycle's readings. */
  grid: OccupancyGrid;
  /** This cycle's range readings, when the robot has range sensors. */
  readings?: RangeReadings;
  /** This cycle's camera frame as a JPEG data URL, when the provider asked for frames. */
  frame?: string;
  /** What became of the previous action. */
  lastResult?: ActionReport;
}

/**
 * Chooses the next navigation action. Implementations must resolve or reject promptly once
 * `signal` is aborted (the bridge aborts it when the run stops or the decision times out), and
 * return a decision that satisfies the decision schema (the bridge checks it again).
 */
export interface DecisionProvider {
  /** A short name for logs and events. */
  readonly name: string;
  /** Whether the provider looks at camera frames (the bridge captures one per cycle only then). */
  readonly wantsFrame?: boolean;
  decide(context: DecisionContext, signal: AbortSignal): Promise<NavigationDecision>;
}
