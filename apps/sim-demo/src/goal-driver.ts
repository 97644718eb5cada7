import { GoalSeekingProvider, NavigationBridge, OccupancyGrid } from '@hal/navigation';
import type { SimulationHAL } from '@hal/simulation';
import type { OccupancyGridView, WorldScene } from '@hal/simulation/three';
import type { ResultsLog } from './results-log.js';
import type { StatusLine } from './status-line.js';

/** Where driving to a clicked goal stands. */
export type GoalState = 'none' | 'driving' | 'reached' | 'failed' | 'cancelled';

type Point = { x: number; y: number };

export interface GoalDriverOptions {
  hal: SimulationHAL;
  /** Draws the goal, the planned path and the occupancy grid. */
  scene: WorldScene;
  log: ResultsLog;
  status: StatusLine;
  /** "Plan around obstacles": drive with the navigation bridge (true) or one straight moveTo. */
  planAroundObstacles: () => boolean;
  /** "Grid": show the navigation occupancy grid on the floor. */
  showGrid: () => boolean;
}

/** The occupancy grid as the scene's overlay wants it: occupancy 0..1, negative unknown. */
function gridView(grid: OccupancyGrid): OccupancyGridView {
  const { spec, logOdds } = grid;
  const data = Array.from(logOdds, (l) => (l === 0 ? -1 : 1 / (1 + Math.exp(-l))));
  return {
    width: spec.width,
    height: spec.height,
    resolution: spec.resolutionM,
    origin: { x: spec.originX, y: spec.originY },
    data,
  };
}

/**
 * Drives the robot to clicked goals. With "Plan around obstacles" the navigation bridge drives
 * there (A* on an occupancy grid seeded with the map, re-planning from the range sensors);
 * without it, one straight moveTo. A new goal, teleop or the e-stop cancels the current one.
 */
export class GoalDriver {
  readonly #options: GoalDriverOptions;
  #goal: Point | undefined;
  #state: GoalState = 'none';
  #serial = 0;
  #plannedPath: Point[] | undefined;
  #grid: OccupancyGrid;
  #bridge: NavigationBridge;
  #shownGridVersion = -1;

  constructor(options: GoalDriverOptions) {
    this.#options = options;
    this.#grid = OccupancyGrid.fromMap(options.hal.world.map);
    this.#bridge = this.#makeBridge();
  }

  get state(): GoalState {
    return this.#state;
  }
  /** The goal being driven to. */
  get goal(): Point | undefined {
    return this.#goal;
  }
  /** The route to it, from where the robot was when it was planned. */
  get plannedPath(): Point[] | undefined {
    return this.#plannedPath;
  }

  /** Drives to (x, y), world metres, cancelling the current goal first. */
  async goTo(x: number, y: number): Promise<void> {
    const { hal, scene, status, log } = this.#options;
    await this.cancel();
    const serial = this.#serial;
    this.#goal = { x, y };
    this.#state = 'driving';
    const robot = hal.robot;
    scene.setGoal(this.#goal);
    const where = `(${x.toFixed(2)}, ${y.toFixed(2)}) m`;
    let ok: boolean;
    let why: string;
    if (this.#options.planAroundObstacles()) {
      status.set(`Planning a route to ${where}…`);
      const outcome = await this.#bridge.run({ x, y });
      ok = outcome.status === 'reached';
      why = `${outcome.reason}: ${outcome.message}`;
    } else {
      this.#plannedPath = [
        { x: robot.x, y: robot.y },
        { x, y },
      ];
      scene.setPlannedPath(this.#plannedPath);
      status.set(`Driving straight to ${where}…`);
      const result = await hal.locomotion.moveTo(x, y, 0);
      log.record(`moveTo(${x.toFixed(2)}, ${y.toFixed(2)})`, result);
      ok = result.success;
      why = `${result.code ?? ''}: ${result.error ?? ''}`;
    }
    if (serial !== this.#serial) return;
    scene.setPlannedPath(undefined);
    this.#plannedPath = undefined;
    if (ok) {
      this.#state = 'reached';
      status.set('Goal reached ✓', 'ok');
    } else {
      this.#state = 'failed';
      status.set(`Stopped: ${why}`, 'bad');
    }
  }

  /** Stops whatever is driving to a goal (and waits until it has). */
  async cancel(): Promise<void> {
    if (this.#state === 'driving') this.#state = 'cancelled';
    this.#serial += 1;
    this.#goal = undefined;
    this.#plannedPath = undefined;
    this.#options.scene.setGoal(undefined);
    this.#options.scene.setPlannedPath(undefined);
    await this.#bridge.stop();
  }

  /** Starts afresh on the world's (new) map: no goal state, a grid seeded with the map. */
  startOver(): void {
    this.#state = 'none';
    this.#grid = OccupancyGrid.fromMap(this.#options.hal.world.map);
    this.#bridge = this.#makeBridge();
    this.showGrid();
  }

  /** Shows the occupancy grid on the floor when "Grid" is on, else removes it. */
  showGrid(): void {
    const { scene } = this.#options;
    scene.setOccupancyGrid(this.#options.showGrid() ? gridView(this.#grid) : undefined);
  }

  /** Once per frame: redraws the shown grid when the bridge has changed it. */
  refreshGrid(): void {
    if (this.#options.showGrid() && this.#grid.version !== this.#shownGridVersion) {
      this.#shownGridVersion = this.#grid.version;
      this.showGrid();
    }
  }

  #makeBridge(): NavigationBridge {
    const { hal, scene, log } = this.#options;
    const made = new NavigationBridge({
      hal,
      provider: new GoalSeekingProvider(),
      grid: this.#grid,
    });
    made.on('path', ({ plan }) => {
      const robot = hal.robot;
      this.#plannedPath = [{ x: robot.x, y: robot.y }, ...plan.waypoints.slice(1)];
      scene.setPlannedPath(this.#plannedPath);
    });
    made.on('result', ({ call, args, result }) => {
      const text = Object.values(args)
        .map((v) => (typeof v === 'number' ? Number(v.toFixed(2)) : String(v)))
        .join(', ');
      log.record(`${call}(${text})`, result);
    });
    return made;
  }
}
