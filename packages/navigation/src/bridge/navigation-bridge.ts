import { errorMessage, scoped, silentLogger, TypedEmitter, withTimeout } from '@hal/types';
import type { HardwareAbstractionLayer } from '@hal/types';
import { distance } from '../grid/geometry.js';
import type { Point } from '../grid/geometry.js';
import { OccupancyGrid } from '../grid/occupancy-grid.js';
import type { DecisionProvider } from '../decision/provider.js';
import { NavigationError } from '../errors.js';
import { resolveBridgeSettings } from './bridge-options.js';
import type { NavigationBridgeOptions } from './bridge-options.js';
import type { BridgeContext, RunState } from './bridge-context.js';
import { runCycles } from './cycle-loop.js';
import type { NavigationEvents } from './navigation-events.js';
import { failed } from './navigation-outcome.js';
import type { NavigationOutcome, Terminal } from './navigation-outcome.js';
import { stopWheels } from './sensing.js';

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
  readonly #ctx: BridgeContext;
  #running = false;
  #controller: AbortController | undefined;
  #ending: Promise<unknown> | undefined;

  constructor(options: NavigationBridgeOptions) {
    this.hal = options.hal;
    this.provider = options.provider;
    const logger = scoped(options.logger ?? silentLogger, 'hal:navigation');
    this.grid = options.grid ?? new OccupancyGrid();
    if (options.map !== undefined) this.grid.seedFromMap(options.map);
    this.#ctx = {
      hal: this.hal,
      grid: this.grid,
      provider: this.provider,
      events: new TypedEmitter<NavigationEvents>((event, error) =>
        logger.error('navigation event listener threw', { event, error: errorMessage(error) }),
      ),
      logger,
      settings: resolveBridgeSettings(options),
      stopRequested: false,
      sensorsAvailable: true,
    };
  }

  /** Adds an event listener; returns a function that removes it. */
  on<K extends keyof NavigationEvents>(
    event: K,
    listener: (payload: NavigationEvents[K]) => void,
  ): () => void {
    return this.#ctx.events.on(event, listener);
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
    this.#ctx.stopRequested = true;
    this.#controller?.abort(new NavigationError('ABORTED', 'the navigation run was stopped'));
    await stopWheels(this.#ctx);
    // The stopped motion resolves at once (INTERRUPTED), so the run ends promptly; wait for it
    // (bounded), so that a new run can start as soon as this resolves.
    const ending = this.#ending;
    if (ending !== undefined) await withTimeout(ending, 2 * this.#ctx.settings.sensorTimeoutMs);
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
    this.#ctx.stopRequested = false;
    const controller = new AbortController();
    this.#controller = controller;
    const onAbort = () => void this.stop();
    options.signal?.addEventListener('abort', onAbort, { once: true });
    const started = this.#ctx.settings.now();
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
      if (options.signal?.aborted) this.#ctx.stopRequested = true;
      const terminal = await runCycles(this.#ctx, state, controller.signal, started);
      return await this.#finish(state, terminal, started);
    } catch (error) {
      // Nothing above should throw; if it does, the run fails rather than rejecting.
      this.#ctx.logger.error('navigation run failed unexpectedly', { error: errorMessage(error) });
      const terminal = failed('HAL_ERROR', `unexpected error: ${errorMessage(error)}`);
      return await this.#finish(state, terminal, started);
    } finally {
      options.signal?.removeEventListener('abort', onAbort);
      this.#running = false;
      this.#controller = undefined;
    }
  }

  async #finish(state: RunState, terminal: Terminal, started: number): Promise<NavigationOutcome> {
    if (terminal.status !== 'reached') await stopWheels(this.#ctx);
    const finalPose = state.trajectory.at(-1);
    const outcome: NavigationOutcome = {
      status: terminal.status,
      reason: terminal.reason,
      message: terminal.message,
      goal: state.goal,
      cycles: state.cycle,
      elapsedMs: this.#ctx.settings.now() - started,
      trajectory: state.trajectory,
    };
    if (finalPose !== undefined) {
      outcome.finalPose = finalPose;
      if (state.goal !== null) outcome.distanceToGoalM = distance(finalPose, state.goal);
    }
    if (state.lastHalResult !== undefined && !state.lastHalResult.success) {
      outcome.lastResult = state.lastHalResult;
    }
    this.#ctx.logger.info('navigation run ended', {
      status: outcome.status,
      reason: outcome.reason,
      cycles: outcome.cycles,
    });
    this.#ctx.events.emit('done', outcome);
    return outcome;
  }
}
