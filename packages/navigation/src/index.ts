export { worldToCell } from './grid/geometry.js';
export type { Cell, GridSpec, Point, Pose2D } from './grid/geometry.js';
export { gridImageDataUrl, renderGridImage } from './grid/image.js';
export type { GridImageOptions, RgbaImage } from './grid/image.js';
export type { KnownMap } from './grid/known-map.js';
export type { CellState, LogOddsModel } from './grid/log-odds.js';
export { OccupancyGrid } from './grid/occupancy-grid.js';
export type { CellCounts, OccupancyGridOptions } from './grid/occupancy-grid.js';
export type { RangeReadings, RangeSensorModel } from './grid/range-sensor-update.js';
export { describeWorld } from './grid/summary.js';
export type { WorldSummaryOptions } from './grid/summary.js';

export { AStarSearch } from './planner/astar.js';
export type { GridSearchResult, GridSearchStatus } from './planner/astar.js';
export { GridPlanner } from './planner/grid-planner.js';
export type { PathPlan, PlanOptions } from './planner/grid-planner.js';
export { simplifyPath } from './planner/line-of-sight.js';
export { ObstacleMap } from './planner/obstacle-map.js';

export { NavigationError } from './errors.js';
export type { NavigationErrorCode } from './errors.js';

export { NavigationDecisionSchema, decisionJsonSchema, parseDecision } from './decision/schema.js';
export type { DecisionBounds, NavigationDecision } from './decision/schema.js';
export type { ActionReport, DecisionContext, DecisionProvider } from './decision/provider.js';
export { FrontierExplorationProvider, GoalSeekingProvider } from './decision/deterministic.js';
export type { FrontierExplorationOptions } from './decision/deterministic.js';
export { OpenAICompatibleProvider } from './decision/llm-provider.js';
export type { OpenAICompatibleOptions, ResponseFormatMode } from './decision/llm-options.js';
export { reachableFrontiers } from './grid/frontier.js';
export type { Frontier, FrontierCell, FrontierOptions } from './grid/frontier.js';

export { NavigationBridge } from './bridge/navigation-bridge.js';
export type { NavigationBridgeOptions } from './bridge/bridge-options.js';
export type { WorldObservation, WorldObserver } from './bridge/world-observer.js';
export type { NavigationEvents } from './bridge/navigation-events.js';
export type {
  NavigationOutcome,
  NavigationOutcomeReason,
  NavigationStatus,
} from './bridge/navigation-outcome.js';
