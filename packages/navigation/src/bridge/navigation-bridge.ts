import { normalizeAngle } from '@hal/kinematics';
import { isHalError, maxLinearSpeedMPerS, V1_ROBOT } from '@hal/types';
import type { HALToolResult, HardwareAbstractionLayer, RobotConfig } from '@hal/types';
import { findFrontier } from '../grid/frontier.js';
import { cellCentre, worldToCell } from '../grid/geometry.js';
import type { Point } from '../grid/geometry.js';
import type { KnownMap } from '../grid/known-map.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { Pose2D, RangeReadings, RangeSensorModel } from '../grid/occupancy-grid.js';
import type { PathPlan } from '../planner/grid-planner.js';
import type { ActionReport, DecisionContext, DecisionProvider } from '../decision/provider.js';
import { parseDecision } from '../decision/schema.js';
import type { NavigationDecision } from '../decision/schema.js';
import { NavigationError, SILENT_LOGGER } from '../errors.js';
import type { NavigationLogger } from '../errors.js';
import { TypedEmitter } from './emitter.js';
import { TIMED_OUT, withTimeout } from './timeouts.js';

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

/** The events a {@link NavigationBridge} emits, for UIs and logs. */
export interface NavigationEvents {
  /** A cycle starts: the pose just read and the range readings. */
  cycle: { cycle: number; pose: Pose2D; readings?: RangeReadings; elapsedMs: number };
  /** The provider decided. */
  decision: { cycle: number; provider: string; decision: NavigationDecision };
  /** A route was planned; `leg` is the point the robot drives to this cycle. */
  path: { cycle: number; target: Point; plan: PathPlan; leg: Point };
  /** A HAL call finished. */
  result: {
    cycle: number;
    call: 'moveTo' | 'rotate' | 'moveForward' | 'moveBackward';
    args: Record<string, unknown>;
    result: HALToolResult;
  };
  /** The run ended. */
  done: NavigationOutcome;
}

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
   * With range sensors, turn to face a leg before driving it when it lies more than this many
   * degrees off the heading (the front sensor looks first). Default 20; `false` drives at once.
   */
  faceBeforeDrivingDeg?: number | false;
  /** Cycles in a row without a route before the run fails UNREACHABLE. Default 4. */
  maxNoPathCycles?: number;
  /** Stuck recoveries allowed in one run before it fails STUCK. Default 3. */
  maxStuckRecoveries?: number;
  /** The clock for the time cap, ms. Default `Date.now`. */
  now?: () => number;
  logger?: NavigationLogger;
}

type Terminal = { status: NavigationStatus; reason: NavigationOutcomeReason; message: string };
type Motion = 'moveTo' | 'rotate' | 'moveForward' | 'moveBackward';
interface Acted {
  report: ActionReport;
  terminal?: Terminal;
  /** Whether the action asked the wheels to move (for stuck detection). */
  moved: boolean;
}

const DEG = Math.PI / 180;
const NUDGE_CM = 10;

function toPose2D(pose: { position: { x: number; y: number }; rotation: { yaw: number } }): Pose2D {
  return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
}

function positive(name: string, value: number, integer = false): number {
  if (!Number.isFinite(value) || value <= 0 || (integer && !Number.isInteger(value))) {
    throw new NavigationError(
      'CONFIG',
      `"${name}" must be a positive ${integer ? 'integer' : 'number'}, got ${value}`,
    );
  }
  return value;
}

/**
 * The navigation loop over any HAL: each cycle reads the pose and the range sensors (updating
 * the world model from the actual pose), captures a frame when the provider wants one, asks the
 * provider for a decision, checks it against the decision schema, and acts: MOVE_TO and EXPLORE
 * follow the A* route one leg per cycle through `locomotion.moveTo`, ROTATE_TO turns to an
 * absolute heading, STOP ends the run. Every HAL result is checked: a collision or the emergency
 * stop ends the run at once; other failures are reported to the provider and retried a few
 * times. Cycles and time are capped and every wait has a timeout, so `run()` always resolves.
 */
export class NavigationBridge {
  readonly grid: OccupancyGrid;
  readonly hal: HardwareAbstractionLayer;
  readonly provider: DecisionProvider;
  readonly #events: TypedEmitter<NavigationEvents>;
  readonly #logger: NavigationLogger;
  readonly #robot: RobotConfig;
  readonly #tolerance: number;
  readonly #maxCycles: number;
  readonly #maxDurationMs: number;
  readonly #decisionTimeoutMs: number;
  readonly #sensorTimeoutMs: number;
  readonly #motionMarginMs: number;
  readonly #maxLegM: number;
  readonly #unknownLegM: number;
  readonly #speed: number | undefined;
  readonly #sensorModel: Partial<RangeSensorModel> | false;
  readonly #maxNoPath: number;
  readonly #faceFirst: boolean;
  readonly #faceFirstDeg: number;
  readonly #maxRecoveries: number;
  readonly #now: () => number;
  #sensorsAvailable = true;
  #running = false;
  #stopRequested = false;
  #controller: AbortController | undefined;
  #ending: Promise<unknown> | undefined;

  constructor(options: NavigationBridgeOptions) {
    this.hal = options.hal;
    this.provider = options.provider;
    this.#logger = options.logger ?? SILENT_LOGGER;
    this.#events = new TypedEmitter(this.#logger);
    this.grid = options.grid ?? new OccupancyGrid();
    if (options.map !== undefined) this.grid.seedFromMap(options.map);
    this.#robot = options.robot ?? V1_ROBOT;
    this.#tolerance = positive('goalToleranceM', options.goalToleranceM ?? 0.1);
    this.#maxCycles = positive('maxCycles', options.maxCycles ?? 200, true);
    this.#maxDurationMs = positive('maxDurationMs', options.maxDurationMs ?? 600_000);
    this.#decisionTimeoutMs = positive('decisionTimeoutMs', options.decisionTimeoutMs ?? 60_000);
    this.#sensorTimeoutMs = positive('sensorTimeoutMs', options.sensorTimeoutMs ?? 5_000);
    this.#motionMarginMs = positive(
      'motionTimeoutMarginMs',
      options.motionTimeoutMarginMs ?? 10_000,
    );
    this.#maxLegM = positive('maxLegM', options.maxLegM ?? 0.5);
    this.#unknownLegM = positive('unknownLegM', options.unknownLegM ?? 0.15);
    this.#speed = options.speed === undefined ? undefined : positive('speed', options.speed);
    this.#sensorModel = options.rangeSensors ?? {};
    this.#maxNoPath = positive('maxNoPathCycles', options.maxNoPathCycles ?? 4, true);
    const face = options.faceBeforeDrivingDeg ?? 20;
    this.#faceFirst = face !== false;
    this.#faceFirstDeg = face === false ? 180 : positive('faceBeforeDrivingDeg', face);
    this.#maxRecoveries = options.maxStuckRecoveries ?? 3;
    this.#now = options.now ?? Date.now;
  }

  /** Adds an event listener; returns a function that removes it. */
  on<K extends keyof NavigationEvents>(
    event: K,
    listener: (payload: NavigationEvents[K]) => void,
  ): () => void {
    return this.#events.on(event, listener);
  }

  /** Whether a run is in progress. */
  get running(): boolean {
    return this.#running;
  }

  /**
   * Ends the current run: the pending decision is cancelled, the wheels are stopped, and `run()`
   * resolves with status `stopped` (reason STOP_REQUESTED). Resolves once that run has ended, so
   * a new `run()` may follow at once. Does nothing when no run is going.
   */
  async stop(): Promise<void> {
    if (!this.#running) return;
    this.#stopRequested = true;
    this.#controller?.abort(new NavigationError('ABORTED', 'the navigation run was stopped'));
    await this.#stopWheels();
    // The stopped motion resolves at once (INTERRUPTED), so the run ends promptly; wait for it
    // (bounded), so that a new run can start as soon as this resolves.
    const ending = this.#ending;
    if (ending !== undefined) await withTimeout(ending, 2 * this.#sensorTimeoutMs);
  }

  /**
   * Drives to `goal` (metres, world frame), or explores when `goal` is null, until the goal is
   * reached or the run stops or fails. Always resolves (it rejects only when a run is already in
   * progress or the goal is not a pair of finite numbers).
   */
  run(goal: Point | null, options: { signal?: AbortSignal } = {}): Promise<NavigationOutcome> {
    if (this.#running) {
      return Promise.reject(
        new NavigationError('CONFIG', 'a navigation run is already in progress'),
      );
    }
    const running = this.#run(goal, options);
    this.#ending = running.catch(() => undefined);
    return running;
  }

  async #run(goal: Point | null, options: { signal?: AbortSignal }): Promise<NavigationOutcome> {
    if (this.#running) {
      throw new NavigationError('CONFIG', 'a navigation run is already in progress');
    }
    if (goal !== null && (!Number.isFinite(goal.x) || !Number.isFinite(goal.y))) {
      throw new NavigationError(
        'CONFIG',
        `"goal" must have finite x and y, got (${goal.x}, ${goal.y})`,
      );
    }
    this.#running = true;
    this.#stopRequested = false;
    const controller = new AbortController();
    this.#controller = controller;
    const onAbort = () => void this.stop();
    options.signal?.addEventListener('abort', onAbort, { once: true });
    const started = this.#now();
    const state: RunState = {
      goal: goal === null ? null : { x: goal.x, y: goal.y },
      cycle: 0,
      trajectory: [],
      noPath: 0,
      halFailures: 0,
      stuck: 0,
      recoveries: 0,
      lastHalResult: undefined,
    };
    try {
      if (options.signal?.aborted) this.#stopRequested = true;
      const terminal = await this.#loop(state, controller.signal, started);
      return await this.#finish(state, terminal, started);
    } catch (error) {
      // Nothing above should throw; if it does, the run fails rather than rejecting.
      this.#logger.error('navigation run failed unexpectedly', {
        error: error instanceof Error ? error.message : String(error),
      });
      return await this.#finish(
        state,
        {
          status: 'failed',
          reason: 'HAL_ERROR',
          message: `unexpected error: ${error instanceof Error ? error.message : String(error)}`,
        },
        started,
      );
    } finally {
      options.signal?.removeEventListener('abort', onAbort);
      this.#running = false;
      this.#controller = undefined;
    }
  }

  async #loop(state: RunState, signal: AbortSignal, started: number): Promise<Terminal> {
    if (!this.hal.isReady()) {
      return {
        status: 'failed',
        reason: 'HAL_ERROR',
        message: 'the HAL is not ready (call initialize())',
      };
    }
    if (
      state.goal !== null &&
      worldToCell(this.grid.spec, state.goal.x, state.goal.y) === undefined
    ) {
      return {
        status: 'failed',
        reason: 'UNREACHABLE',
        message: `the goal (${state.goal.x}, ${state.goal.y}) lies outside the world model`,
      };
    }
    const first = await this.#readPose();
    if ('terminal' in first) return first.terminal;
    let pose = first.pose;
    state.trajectory.push(pose);
    let lastResult: ActionReport | undefined;

    for (;;) {
      if (this.#stopRequested) {
        return { status: 'stopped', reason: 'STOP_REQUESTED', message: 'the run was stopped' };
      }
      if (this.hal.safety.isEmergencyStopped()) {
        return {
          status: 'failed',
          reason: 'EMERGENCY_STOPPED',
          message: 'the emergency stop is latched',
        };
      }
      if (state.goal !== null && distance(pose, state.goal) <= this.#tolerance) {
        return {
          status: 'reached',
          reason: 'GOAL_REACHED',
          message: `reached the goal (within ${distance(pose, state.goal).toFixed(3)} m)`,
        };
      }
      const elapsed = this.#now() - started;
      if (elapsed > this.#maxDurationMs) {
        return {
          status: 'failed',
          reason: 'TIME_LIMIT',
          message: `no result within ${this.#maxDurationMs} ms`,
        };
      }
      if (state.cycle >= this.#maxCycles) {
        return {
          status: 'failed',
          reason: 'MAX_CYCLES',
          message: `no result within ${this.#maxCycles} cycles`,
        };
      }
      state.cycle += 1;

      // Sense: the world model follows the actual pose.
      this.grid.markFree(pose.x, pose.y, this.grid.robotRadiusM);
      const readings = await this.#readRanges(pose);
      const frame = this.provider.wantsFrame === true ? await this.#captureFrame() : undefined;
      const cycleEvent: NavigationEvents['cycle'] = {
        cycle: state.cycle,
        pose,
        elapsedMs: elapsed,
      };
      if (readings !== undefined) cycleEvent.readings = readings;
      this.#events.emit('cycle', cycleEvent);

      // Decide.
      const context: DecisionContext = {
        cycle: state.cycle,
        goal: state.goal,
        goalToleranceM: this.#tolerance,
        pose,
        grid: this.grid,
      };
      if (readings !== undefined) context.readings = readings;
      if (frame !== undefined) context.frame = frame;
      if (lastResult !== undefined) context.lastResult = lastResult;
      const decided = await this.#decide(context, signal);
      if ('terminal' in decided) return decided.terminal;
      const decision = decided.decision;
      this.#events.emit('decision', { cycle: state.cycle, provider: this.provider.name, decision });

      // Act.
      const acted = await this.#act(state, decision, pose);
      if (acted.terminal !== undefined) {
        if (acted.moved) await this.#refreshPose(state);
        return acted.terminal;
      }
      lastResult = acted.report;
      const after = await this.#readPose();
      if ('terminal' in after) return after.terminal;
      const moved = distance(after.pose, pose);
      const turned = Math.abs(normalizeAngle(after.pose.yaw - pose.yaw));
      pose = after.pose;
      state.trajectory.push(pose);

      // Stuck: motion commands that leave the robot where it was.
      if (acted.moved && moved < 0.01 && turned < DEG) state.stuck += 1;
      else if (moved >= 0.01 || turned >= DEG) state.stuck = 0;
      if (state.stuck >= 2) {
        state.stuck = 0;
        state.recoveries += 1;
        if (state.recoveries > this.#maxRecoveries) {
          return {
            status: 'failed',
            reason: 'STUCK',
            message: `the robot did not move despite ${this.#maxRecoveries} recoveries`,
          };
        }
        const recovered = await this.#recoverFromStuck(state, pose);
        if (recovered !== undefined) return recovered;
        const again = await this.#readPose();
        if ('terminal' in again) return again.terminal;
        pose = again.pose;
        state.trajectory.push(pose);
      }
    }
  }

  async #decide(
    context: DecisionContext,
    runSignal: AbortSignal,
  ): Promise<{ decision: NavigationDecision } | { terminal: Terminal }> {
    const timeout = new AbortController();
    const signal = AbortSignal.any([runSignal, timeout.signal]);
    let answer: NavigationDecision | typeof TIMED_OUT;
    try {
      answer = await withTimeout(this.provider.decide(context, signal), this.#decisionTimeoutMs);
    } catch (error) {
      if (this.#stopRequested) {
        return {
          terminal: { status: 'stopped', reason: 'STOP_REQUESTED', message: 'the run was stopped' },
        };
      }
      return {
        terminal: {
          status: 'failed',
          reason: 'PROVIDER_ERROR',
          message: `${this.provider.name} gave no decision: ${error instanceof Error ? error.message : String(error)}`,
        },
      };
    }
    if (answer === TIMED_OUT) {
      timeout.abort(new NavigationError('TIMEOUT', 'decision timed out'));
      if (this.#stopRequested) {
        return {
          terminal: { status: 'stopped', reason: 'STOP_REQUESTED', message: 'the run was stopped' },
        };
      }
      return {
        terminal: {
          status: 'failed',
          reason: 'PROVIDER_ERROR',
          message: `${this.provider.name} gave no decision within ${this.#decisionTimeoutMs} ms`,
        },
      };
    }
    // Safety layer 1: the decision is checked before anything moves.
    const parsed = parseDecision(answer);
    if (!parsed.ok) {
      return {
        terminal: {
          status: 'failed',
          reason: 'INVALID_DECISION',
          message: `${this.provider.name} gave an invalid decision: ${parsed.problem}`,
        },
      };
    }
    return { decision: parsed.decision };
  }

  async #act(state: RunState, decision: NavigationDecision, pose: Pose2D): Promise<Acted> {
    const action = decision.action;
    switch (action.type) {
      case 'STOP': {
        const report: ActionReport = { action: 'STOP', success: true };
        if (state.goal === null) {
          return decision.goal_reached
            ? {
                report,
                moved: false,
                terminal: {
                  status: 'reached',
                  reason: 'EXPLORATION_COMPLETE',
                  message: `exploration complete: ${decision.reasoning}`,
                },
              }
            : {
                report,
                moved: false,
                terminal: {
                  status: 'stopped',
                  reason: 'PROVIDER_STOPPED',
                  message: `the provider stopped: ${decision.reasoning}`,
                },
              };
        }
        const away = distance(pose, state.goal);
        if (away <= this.#tolerance) {
          return {
            report,
            moved: false,
            terminal: { status: 'reached', reason: 'GOAL_REACHED', message: 'reached the goal' },
          };
        }
        const claim = decision.goal_reached ? ' (it claimed the goal was reached)' : '';
        return {
          report,
          moved: false,
          terminal: {
            status: 'stopped',
            reason: 'PROVIDER_STOPPED',
            message: `the provider stopped ${away.toFixed(2)} m from the goal${claim}: ${decision.reasoning}`,
          },
        };
      }
      case 'ROTATE_TO': {
        // Absolute heading, degrees, counter-clockwise from +x (see the decision schema).
        const delta = normalizeAngle(action.yaw_deg * DEG - pose.yaw) / DEG;
        if (Math.abs(delta) < 0.5)
          return { report: { action: 'ROTATE_TO', success: true }, moved: false };
        return this.#motion(state, 'ROTATE_TO', 'rotate', {
          direction: delta > 0 ? 'left' : 'right',
          degrees: Math.abs(delta),
        });
      }
      case 'EXPLORE': {
        const frontier = findFrontier(this.grid, pose);
        if (frontier === undefined) {
          return this.#noRoute(
            state,
            'EXPLORE',
            pose,
            'no-frontier',
            'no reachable unexplored area is left',
          );
        }
        return this.#follow(state, 'EXPLORE', pose, frontier.target);
      }
      case 'MOVE_TO':
        return this.#follow(state, 'MOVE_TO', pose, { x: action.x, y: action.y });
    }
  }

  /** Plans to `target` and drives the first leg of the route. */
  async #follow(
    state: RunState,
    action: 'MOVE_TO' | 'EXPLORE',
    pose: Pose2D,
    target: Point,
  ): Promise<Acted> {
    let goalPoint = target;
    let plan = this.grid.plan(pose, goalPoint);
    if (plan.status === 'goal-blocked' && plan.goalCell !== undefined) {
      // Go as near as the robot may stand: the nearest free cell within the goal tolerance plus
      // the robot's footprint.
      const reach =
        (this.#tolerance + this.grid.robotRadiusM + this.grid.clearanceM) /
        this.grid.spec.resolutionM;
      const free = this.grid.obstacles.nearestFree(plan.goalCell.cx, plan.goalCell.cy, reach);
      if (free !== undefined) {
        goalPoint = cellCentre(this.grid.spec, free.cx, free.cy);
        plan = this.grid.plan(pose, goalPoint);
      }
    }
    if (plan.status === 'start-blocked' && plan.startCell !== undefined) {
      // Too near an obstacle to plan from here: step to the nearest cell the robot may stand on.
      const reach = 0.3 / this.grid.spec.resolutionM;
      const free = this.grid.obstacles.nearestFree(plan.startCell.cx, plan.startCell.cy, reach);
      if (free !== undefined) {
        const leg = cellCentre(this.grid.spec, free.cx, free.cy);
        this.#events.emit('path', { cycle: state.cycle, target, plan, leg });
        return this.#motion(state, action, 'moveTo', { x: leg.x, y: leg.y });
      }
    }
    if (plan.status === 'unreachable' && this.grid.forgetWeakObstacles() > 0) {
      // Stray readings may have closed the way: forget the obstacles only one or two readings
      // saw, and try once more (the sensors will put back whatever is really there).
      this.#logger.info('navigation: no route; forgot weak obstacles and planned again');
      plan = this.grid.plan(pose, goalPoint);
    }
    if (plan.status !== 'found') {
      return this.#noRoute(
        state,
        action,
        pose,
        plan.status,
        `no route to (${target.x.toFixed(2)}, ${target.y.toFixed(2)}): ${plan.status}`,
      );
    }
    state.noPath = 0;
    // The route ends at the goal cell's centre; end it at the target itself when the robot may
    // stand there.
    const waypoints = plan.waypoints.slice();
    if (waypoints.length > 1 && this.grid.isTraversable(goalPoint.x, goalPoint.y)) {
      waypoints[waypoints.length - 1] = goalPoint;
    }
    const next = waypoints.find((p, k) => k > 0 && distance(pose, p) > 0.01) ?? waypoints.at(-1);
    if (next === undefined || distance(pose, next) <= 0.01) {
      return { report: { action, success: true }, moved: false };
    }
    const span = distance(pose, next);
    // Into unknown space, with range sensors, take short steps: each cycle's readings then map
    // what the robot passes (a thin wall seen side-on from far apart poses comes out as dashes).
    const limit =
      this.#sensorsInUse() && this.#entersUnknown(pose, next)
        ? Math.min(this.#maxLegM, this.#unknownLegM)
        : this.#maxLegM;
    const leg =
      span <= limit
        ? next
        : {
            x: pose.x + ((next.x - pose.x) * limit) / span,
            y: pose.y + ((next.y - pose.y) * limit) / span,
          };
    this.#events.emit('path', { cycle: state.cycle, target, plan: { ...plan, waypoints }, leg });
    // Look before driving: with range sensors, first turn to face the leg, so the front sensor
    // has seen it before the wheels go (the next cycle re-plans with what it saw).
    const heading = Math.atan2(leg.y - pose.y, leg.x - pose.x);
    const turn = normalizeAngle(heading - pose.yaw) / DEG;
    if (this.#faceFirst && this.#sensorsInUse() && Math.abs(turn) > this.#faceFirstDeg) {
      return this.#motion(state, action, 'rotate', {
        direction: turn > 0 ? 'left' : 'right',
        degrees: Math.abs(turn),
      });
    }
    return this.#motion(state, action, 'moveTo', { x: leg.x, y: leg.y });
  }

  /**
   * No route this cycle: the seed's recovery (nudge forward 10 cm) when the cells ahead are free,
   * else a quarter turn to look elsewhere; too many cycles in a row without a route fail the run.
   */
  async #noRoute(
    state: RunState,
    action: 'MOVE_TO' | 'EXPLORE',
    pose: Pose2D,
    code: string,
    message: string,
  ): Promise<Acted> {
    state.noPath += 1;
    if (state.noPath >= this.#maxNoPath) {
      return {
        report: { action, success: false, code, error: message },
        moved: false,
        terminal: {
          status: 'failed',
          reason: 'UNREACHABLE',
          message: `${message}, for ${state.noPath} cycles in a row`,
        },
      };
    }
    const ahead = {
      x: pose.x + (NUDGE_CM / 100 + this.grid.spec.resolutionM) * Math.cos(pose.yaw),
      y: pose.y + (NUDGE_CM / 100 + this.grid.spec.resolutionM) * Math.sin(pose.yaw),
    };
    const acted = this.grid.isTraversable(ahead.x, ahead.y)
      ? await this.#motion(state, action, 'moveForward', { distanceCm: NUDGE_CM })
      : await this.#motion(state, action, 'rotate', { direction: 'left', degrees: 90 });
    if (acted.terminal !== undefined) return acted;
    return { ...acted, report: { action, success: false, code, error: message } };
  }

  /** Backs off and turns away after motions that left the robot where it was. */
  async #recoverFromStuck(state: RunState, pose: Pose2D): Promise<Terminal | undefined> {
    this.#logger.warn('navigation: the robot is stuck; recovering', { recovery: state.recoveries });
    // Whatever is ahead is in the way: tell the world model, so the planner routes around it.
    const reach = this.grid.robotRadiusM + this.grid.spec.resolutionM;
    const ahead = worldToCell(
      this.grid.spec,
      pose.x + reach * Math.cos(pose.yaw),
      pose.y + reach * Math.sin(pose.yaw),
    );
    if (ahead !== undefined) this.grid.addEvidence(ahead.cx, ahead.cy, 2 * this.grid.model.hit);
    const back = {
      x: pose.x - (NUDGE_CM / 100 + this.grid.spec.resolutionM) * Math.cos(pose.yaw),
      y: pose.y - (NUDGE_CM / 100 + this.grid.spec.resolutionM) * Math.sin(pose.yaw),
    };
    if (this.grid.isTraversable(back.x, back.y)) {
      const backed = await this.#motion(state, 'MOVE_TO', 'moveBackward', { distanceCm: NUDGE_CM });
      if (backed.terminal !== undefined) return backed.terminal;
    }
    const turned = await this.#motion(state, 'MOVE_TO', 'rotate', {
      direction: state.recoveries % 2 === 1 ? 'left' : 'right',
      degrees: 90,
    });
    return turned.terminal;
  }

  /** Runs one motion call with a timeout and turns its result into the bridge's terms. */
  async #motion(
    state: RunState,
    action: ActionReport['action'],
    call: Motion,
    args: Record<string, number | string>,
  ): Promise<Acted> {
    const loco = this.hal.locomotion;
    const timeoutMs = this.#motionTimeout(call, args);
    const invoke = (): Promise<HALToolResult> => {
      switch (call) {
        case 'moveTo':
          return loco.moveTo(args['x'] as number, args['y'] as number, 0, this.#speed);
        case 'rotate':
          return loco.rotate(args['direction'] as 'left' | 'right', args['degrees'] as number);
        case 'moveForward':
          return loco.moveForward(args['distanceCm'] as number);
        case 'moveBackward':
          return loco.moveBackward(args['distanceCm'] as number);
      }
    };
    let result: HALToolResult;
    try {
      const answer = await withTimeout(invoke(), timeoutMs);
      if (answer === TIMED_OUT) {
        await this.#stopWheels();
        result = {
          success: false,
          code: 'TIMEOUT',
          error: `${call} did not finish within ${Math.round(timeoutMs)} ms (the bridge's limit)`,
          timestamp: this.#now(),
          mode: this.hal.mode,
        };
      } else {
        result = answer;
      }
    } catch (error) {
      // A HAL must not throw from a motion call; treat it as a hardware error if one does.
      const halError = isHalError(error) ? error : undefined;
      result = {
        success: false,
        code: halError?.code ?? 'HARDWARE_ERROR',
        error: error instanceof Error ? error.message : String(error),
        timestamp: this.#now(),
        mode: this.hal.mode,
      };
    }
    this.#events.emit('result', { cycle: state.cycle, call, args, result });
    state.lastHalResult = result;
    const report: ActionReport = { action, success: result.success };
    if (result.error !== undefined) report.error = result.error;
    if (result.code !== undefined) report.code = result.code;
    if (result.success) {
      state.halFailures = 0;
      return { report, moved: true };
    }
    const why = `${call} failed (${result.code ?? 'no code'}): ${result.error ?? 'no message'}`;
    switch (result.code) {
      case 'COLLISION':
        return {
          report,
          moved: true,
          terminal: { status: 'failed', reason: 'COLLISION', message: why },
        };
      case 'EMERGENCY_STOPPED':
        return {
          report,
          moved: false,
          terminal: { status: 'failed', reason: 'EMERGENCY_STOPPED', message: why },
        };
      case 'TIMEOUT':
        return {
          report,
          moved: true,
          terminal: { status: 'failed', reason: 'TIMEOUT', message: why },
        };
      case 'NOT_READY':
      case 'NOT_CONNECTED':
        return {
          report,
          moved: false,
          terminal: { status: 'failed', reason: 'HAL_ERROR', message: why },
        };
      case 'INTERRUPTED':
        if (this.#stopRequested) {
          return {
            report,
            moved: true,
            terminal: {
              status: 'stopped',
              reason: 'STOP_REQUESTED',
              message: 'the run was stopped',
            },
          };
        }
        break;
      default:
        break;
    }
    state.halFailures += 1;
    this.#logger.warn('navigation: motion failed', {
      call,
      code: result.code,
      error: result.error,
    });
    if (state.halFailures >= 3) {
      return {
        report,
        moved: true,
        terminal: {
          status: 'failed',
          reason: 'HAL_ERROR',
          message: `${why} (3 failures in a row)`,
        },
      };
    }
    // Failed motions count toward halFailures, not toward being stuck.
    return { report, moved: false };
  }

  /** A motion's timeout: its expected duration at the robot's speed, doubled, plus a margin. */
  #motionTimeout(call: Motion, args: Record<string, number | string>): number {
    const speed = Math.min(this.#speed ?? Infinity, maxLinearSpeedMPerS(this.#robot));
    const halfBaseM = this.#robot.wheelBaseCm / 200;
    let metres = 0;
    if (call === 'moveTo') {
      // A turn of up to half a revolution, then the straight leg.
      metres = Math.PI * halfBaseM + this.#maxLegM * 1.5;
    } else if (call === 'rotate') {
      metres = Number(args['degrees']) * DEG * halfBaseM;
    } else {
      metres = Number(args['distanceCm']) / 100;
    }
    return this.#motionMarginMs + (2 * metres * 1000) / speed;
  }

  async #readPose(): Promise<{ pose: Pose2D } | { terminal: Terminal }> {
    try {
      const answer = await withTimeout(this.hal.locomotion.getPose(), this.#sensorTimeoutMs);
      if (answer === TIMED_OUT) {
        return {
          terminal: {
            status: 'failed',
            reason: 'TIMEOUT',
            message: `getPose gave no answer within ${this.#sensorTimeoutMs} ms`,
          },
        };
      }
      const pose = toPose2D(answer);
      if (![pose.x, pose.y, pose.yaw].every(Number.isFinite)) {
        return {
          terminal: {
            status: 'failed',
            reason: 'HAL_ERROR',
            message: 'getPose returned a non-finite pose',
          },
        };
      }
      return { pose };
    } catch (error) {
      return {
        terminal: {
          status: 'failed',
          reason: 'HAL_ERROR',
          message: `getPose failed: ${error instanceof Error ? error.message : String(error)}`,
        },
      };
    }
  }

  /** Reads the pose once more after a run-ending action, for the trajectory. */
  async #refreshPose(state: RunState): Promise<void> {
    const read = await this.#readPose();
    if ('pose' in read) {
      state.trajectory.push(read.pose);
      const last = state.lastHalResult;
      if (last?.code === 'COLLISION') {
        // Record what the robot ran into, just ahead of where it stopped.
        const p = read.pose;
        const reach = this.grid.robotRadiusM + this.grid.spec.resolutionM / 2;
        const cell = worldToCell(
          this.grid.spec,
          p.x + reach * Math.cos(p.yaw),
          p.y + reach * Math.sin(p.yaw),
        );
        if (cell !== undefined) this.grid.addEvidence(cell.cx, cell.cy, 2 * this.grid.model.hit);
      }
    }
  }

  /** Whether the robot's footprint, swept from `from` to `to`, touches an unknown cell. */
  #entersUnknown(from: Point, to: Point): boolean {
    const { resolutionM } = this.grid.spec;
    const reach = this.grid.robotRadiusM + resolutionM / 2;
    const length = distance(from, to);
    const steps = Math.max(1, Math.ceil(length / (resolutionM / 2)));
    const ring = Math.ceil(reach / resolutionM);
    for (let k = 1; k <= steps; k += 1) {
      const x = from.x + ((to.x - from.x) * k) / steps;
      const y = from.y + ((to.y - from.y) * k) / steps;
      const centre = worldToCell(this.grid.spec, x, y);
      if (centre === undefined) continue;
      for (let dy = -ring; dy <= ring; dy += 1) {
        for (let dx = -ring; dx <= ring; dx += 1) {
          const c = cellCentre(this.grid.spec, centre.cx + dx, centre.cy + dy);
          if (Math.hypot(c.x - x, c.y - y) > reach) continue;
          if (this.grid.stateOf(centre.cx + dx, centre.cy + dy) === 'unknown') return true;
        }
      }
    }
    return false;
  }

  #sensorsInUse(): boolean {
    return this.#sensorModel !== false && this.#sensorsAvailable;
  }

  async #readRanges(pose: Pose2D): Promise<RangeReadings | undefined> {
    if (this.#sensorModel === false || !this.#sensorsAvailable) return undefined;
    try {
      const answer = await withTimeout(this.hal.vision.getDistanceSensors(), this.#sensorTimeoutMs);
      if (answer === TIMED_OUT) {
        this.#logger.warn('navigation: range sensors gave no answer in time');
        return undefined;
      }
      if (answer.source === 'unavailable') {
        this.#sensorsAvailable = false;
        return undefined;
      }
      this.grid.integrateRangeReadings(pose, answer, this.#sensorModel);
      return answer;
    } catch (error) {
      if (isHalError(error) && error.code === 'NOT_IMPLEMENTED') {
        this.#sensorsAvailable = false;
        this.#logger.info(
          'navigation: the robot has no range sensors; mapping from the known map only',
        );
      } else {
        this.#logger.warn('navigation: reading the range sensors failed', {
          error: error instanceof Error ? error.message : String(error),
        });
      }
      return undefined;
    }
  }

  async #captureFrame(): Promise<string | undefined> {
    try {
      const answer = await withTimeout(this.hal.vision.captureFrame(), this.#sensorTimeoutMs);
      return answer === TIMED_OUT ? undefined : answer;
    } catch (error) {
      this.#logger.warn('navigation: no camera frame', {
        error: error instanceof Error ? error.message : String(error),
      });
      return undefined;
    }
  }

  async #stopWheels(): Promise<void> {
    if (!this.hal.isReady()) return;
    try {
      await withTimeout(this.hal.locomotion.stop(), this.#sensorTimeoutMs);
    } catch {
      // Best effort: the run is ending anyway.
    }
  }

  async #finish(state: RunState, terminal: Terminal, started: number): Promise<NavigationOutcome> {
    if (terminal.status !== 'reached') await this.#stopWheels();
    const finalPose = state.trajectory.at(-1);
    const outcome: NavigationOutcome = {
      status: terminal.status,
      reason: terminal.reason,
      message: terminal.message,
      goal: state.goal,
      cycles: state.cycle,
      elapsedMs: this.#now() - started,
      trajectory: state.trajectory,
    };
    if (finalPose !== undefined) {
      outcome.finalPose = finalPose;
      if (state.goal !== null) outcome.distanceToGoalM = distance(finalPose, state.goal);
    }
    if (state.lastHalResult !== undefined && !state.lastHalResult.success) {
      outcome.lastResult = state.lastHalResult;
    }
    this.#logger.info('navigation run ended', {
      status: outcome.status,
      reason: outcome.reason,
      cycles: outcome.cycles,
    });
    this.#events.emit('done', outcome);
    return outcome;
  }
}

interface RunState {
  goal: Point | null;
  cycle: number;
  trajectory: Pose2D[];
  noPath: number;
  halFailures: number;
  stuck: number;
  recoveries: number;
  lastHalResult: HALToolResult | undefined;
}

function distance(a: Point, b: Point): number {
  return Math.hypot(a.x - b.x, a.y - b.y);
}
