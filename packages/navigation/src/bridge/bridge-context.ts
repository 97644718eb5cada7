import type {
  HALToolResult,
  HardwareAbstractionLayer,
  ScopedLogger,
  TypedEmitter,
} from '@hal/types';
import type { Point, Pose2D } from '../grid/geometry.js';
import type { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { ActionReport, DecisionProvider } from '../decision/provider.js';
import type { BridgeSettings } from './bridge-options.js';
import type { NavigationEvents } from './navigation-events.js';
import type { Terminal } from './navigation-outcome.js';

/** What the parts of the bridge share: the robot, the world model, the settings and two flags. */
export interface BridgeContext {
  readonly hal: HardwareAbstractionLayer;
  readonly grid: OccupancyGrid;
  readonly provider: DecisionProvider;
  readonly events: TypedEmitter<NavigationEvents>;
  readonly logger: ScopedLogger;
  readonly settings: BridgeSettings;
  /** Set by `stop()`; cleared when a run starts. */
  stopRequested: boolean;
  /** Cleared for good once the robot turns out to have no range sensors. */
  sensorsAvailable: boolean;
}

/** One run's bookkeeping. */
export interface RunState {
  goal: Point | null;
  cycle: number;
  /** Every pose read: the start, then one after each action. */
  trajectory: Pose2D[];
  /** Cycles in a row without a route. */
  noPath: number;
  /** Failed motions in a row. */
  halFailures: number;
  /** Motions in a row that succeeded but left the robot where it was. */
  stuck: number;
  /** Stuck recoveries so far. */
  recoveries: number;
  lastHalResult: HALToolResult | undefined;
}

/** What became of one action. */
export interface Acted {
  report: ActionReport;
  terminal?: Terminal;
  /** Whether the action asked the wheels to move (for stuck detection). */
  moved: boolean;
}

/** Whether range readings feed the world model: wanted, and the robot has the sensors. */
export function sensorsInUse(ctx: BridgeContext): boolean {
  return ctx.settings.rangeSensors !== false && ctx.sensorsAvailable;
}
