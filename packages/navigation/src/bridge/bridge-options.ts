import { V1_ROBOT } from '@hal/types';
import type { HardwareAbstractionLayer, RobotConfig } from '@hal/types';
import type { KnownMap } from '../grid/known-map.js';
import type { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { RangeSensorModel } from '../grid/range-sensor-update.js';
import type { DecisionProvider } from '../decision/provider.js';
import type { WorldObserver } from './world-observer.js';
import { NavigationError, positiveOption } from '../errors.js';
import type { Logger } from '@hal/types';

/** Options of a {@link NavigationBridge}. */
export interface NavigationBridgeOptions {
  /** The robot, driven only through its public HAL interface. */
  hal: HardwareAbstractionLayer;
  /** Who decides each cycle's action. */
  provider: DecisionProvider;
  /** The world model. Default a new 5 m x 5 m grid at 5 cm. */
  grid?: OccupancyGrid;
  /** A known map to seed the world model with (walls, obstacles, arena). */
  map?: KnownMap;
  /** The robot's limits, for motion time estimates. Default the V1 robot. */
  robot?: RobotConfig;
  /** How close to the goal counts as there, metres. Default 0.1. */
  goalToleranceM?: number;
  /** Most decision cycles in one run. Default 200. */
  maxCycles?: number;
  /** Longest run, ms. Default 600000 (10 minutes). */
  maxDurationMs?: number;
  /** Longest wait for one decision, ms. Default 60000. */
  decisionTimeoutMs?: number;
  /** Longest wait for a pose, range reading or camera frame, ms. Default 5000. */
  sensorTimeoutMs?: number;
  /** Added to a motion's expected duration to get its timeout, ms. Default 10000. */
  motionTimeoutMarginMs?: number;
  /** Longest straight leg driven in one cycle, metres (then the bridge senses and re-plans). Default 0.5. */
  maxLegM?: number;
  /**
   * Longest leg, metres, when the robot's footprint along it touches unknown cells and range
   * sensors are in use: short steps map what the robot passes. Default 0.15.
   */
  unknownLegM?: number;
  /** Cruise speed for moveTo, m/s. Default the robot's top speed. */
  speed?: number;
  /** Range sensor model for the world model, or false to ignore range sensors. */
  rangeSensors?: Partial<RangeSensorModel> | false;
  /**
   * With range sensors or an `observe`r, turn to face a leg before driving it when it lies more than this many
   * degrees off the heading (the front sensor looks first). Default 20; `false` drives at once.
   */
  faceBeforeDrivingDeg?: number | false;
  /**
   * What the bridge perceives each cycle beside its range sensors (a camera pipeline): called
   * after the range sensors are read, with a frame captured for it and the pose, to update the
   * grid before the provider decides. Bounded by `sensorTimeoutMs`. Default none.
   */
  observe?: WorldObserver;
  /**
   * Take the pose after an action from the motion's result (`data.pose`, the robot's odometry)
   * when it carries one, and keep the pose when nothing moved, instead of reading it with
   * `getPose` after every action: one call fewer per cycle where calls are counted. Default false.
   */
  poseFromResults?: boolean;
  /** Cycles in a row without a route before the run fails UNREACHABLE. Default 4. */
  maxNoPathCycles?: number;
  /** Stuck recoveries allowed in one run before it fails STUCK. Default 3. */
  maxStuckRecoveries?: number;
  /** The clock for the time cap, ms. Default `Date.now`. */
  now?: () => number;
  logger?: Logger;
}

/** A bridge's options with every default filled in and every number checked. */
export interface BridgeSettings {
  readonly robot: RobotConfig;
  readonly goalToleranceM: number;
  readonly maxCycles: number;
  readonly maxDurationMs: number;
  readonly decisionTimeoutMs: number;
  readonly sensorTimeoutMs: number;
  readonly motionTimeoutMarginMs: number;
  readonly maxLegM: number;
  readonly unknownLegM: number;
  readonly speed: number | undefined;
  readonly rangeSensors: Partial<RangeSensorModel> | false;
  /** Whether to turn to face a leg before driving it (range sensors permitting). */
  readonly faceFirst: boolean;
  /** How far off the heading a leg may lie before the robot turns to face it, degrees. */
  readonly faceFirstDeg: number;
  readonly maxNoPathCycles: number;
  readonly maxStuckRecoveries: number;
  /** The world observer, if any. */
  readonly observe: WorldObserver | undefined;
  readonly poseFromResults: boolean;
  readonly now: () => number;
}

/** Fills in the defaults; throws a CONFIG NavigationError naming a bad option. */
export function resolveBridgeSettings(options: NavigationBridgeOptions): BridgeSettings {
  const face = options.faceBeforeDrivingDeg ?? 20;
  return {
    robot: options.robot ?? V1_ROBOT,
    goalToleranceM: positiveOption('goalToleranceM', options.goalToleranceM ?? 0.1),
    maxCycles: positiveOption('maxCycles', options.maxCycles ?? 200, true),
    maxDurationMs: positiveOption('maxDurationMs', options.maxDurationMs ?? 600_000),
    decisionTimeoutMs: positiveOption('decisionTimeoutMs', options.decisionTimeoutMs ?? 60_000),
    sensorTimeoutMs: positiveOption('sensorTimeoutMs', options.sensorTimeoutMs ?? 5_000),
    motionTimeoutMarginMs: positiveOption(
      'motionTimeoutMarginMs',
      options.motionTimeoutMarginMs ?? 10_000,
    ),
    maxLegM: positiveOption('maxLegM', options.maxLegM ?? 0.5),
    unknownLegM: positiveOption('unknownLegM', options.unknownLegM ?? 0.15),
    speed: options.speed === undefined ? undefined : positiveOption('speed', options.speed),
    rangeSensors: options.rangeSensors ?? {},
    maxNoPathCycles: positiveOption('maxNoPathCycles', options.maxNoPathCycles ?? 4, true),
    faceFirst: face !== false,
    faceFirstDeg: face === false ? 180 : positiveOption('faceBeforeDrivingDeg', face),
    maxStuckRecoveries: options.maxStuckRecoveries ?? 3,
    observe: checkObserver(options.observe),
    poseFromResults: options.poseFromResults === true,
    now: options.now ?? Date.now,
  };
}

function checkObserver(observe: unknown): WorldObserver | undefined {
  if (observe === undefined || typeof observe === 'function') return observe as WorldObserver;
  throw new NavigationError('CONFIG', `"observe" must be a function, got ${typeof observe}`);
}
