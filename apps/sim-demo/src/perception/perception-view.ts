import { Perception } from '@hal/perception';
import type { Look } from '@hal/perception';
import type { OccupancyGrid } from '@hal/navigation';
import type { SimulationHAL, WorldMap } from '@hal/simulation';
import type { WorldScene } from '@hal/simulation/three';
import { V1_CAMERA, errorMessage } from '@hal/types';
import type { CameraModel } from '@hal/types';
import { make } from '../dom.js';
import { CameraBoxes } from './camera-boxes.js';
import { emptyGridOf, perceivedGridView } from './perceived-grid.js';

/** Time between two looks, ms (a look takes a frame, decodes it and perceives it). */
const LOOK_EVERY_MS = 250;

export interface PerceptionViewOptions {
  /** The selected robot's HAL (perception uses only its public calls). */
  hal: SimulationHAL;
  /** Where the perceived grid is drawn on the floor. */
  scene: WorldScene;
  /** "Perception": on runs it on the robot's frames. */
  toggle: HTMLInputElement;
  /** Lies over the camera view: the boxes and the free-space boundary go here. */
  overlay: HTMLCanvasElement;
  /** The list of what is seen. */
  list: HTMLElement;
  /** Called when the toggle goes off: the floor overlay is the navigation grid's again. */
  onOff: () => void;
}

/** What the view shows, for the page's hooks. */
export interface PerceptionViewState {
  enabled: boolean;
  /** Looks taken since it was turned on. */
  looks: number;
  /** The last look's objects. */
  objects: Array<{ label: string; bearingDeg: number; distanceM: number; x: number; y: number }>;
  /** Cells of the perceived grid that are free and occupied. */
  cells: { free: number; occupied: number };
  /** The last look's failure, if it failed. */
  error?: string;
}

/**
 * The demo's Perception toggle: while on, `Perception` (the package the cube runs) looks through
 * the selected robot's camera a few times a second; the objects it finds are boxed on the camera
 * view and listed, and the free space it sees is laid into a grid of its own, drawn on the floor
 * of the 3D scene. A new robot or a new map starts afresh (new memory, new grid, floor learnt
 * again).
 */
export class PerceptionView {
  readonly #options: PerceptionViewOptions;
  readonly #boxes: CameraBoxes;
  #perception: Perception | undefined;
  #grid: OccupancyGrid | undefined;
  #for: { robot: string; map: WorldMap } | undefined;
  #timer: ReturnType<typeof setTimeout> | undefined;
  #state: PerceptionViewState = {
    enabled: false,
    looks: 0,
    objects: [],
    cells: { free: 0, occupied: 0 },
  };

  constructor(options: PerceptionViewOptions) {
    this.#options = options;
    this.#boxes = new CameraBoxes(options.overlay);
    options.toggle.addEventListener('change', () => {
      options.toggle.blur();
      if (options.toggle.checked) this.#start();
      else this.#stop();
    });
  }

  /** Whether it runs (the floor overlay is then the perceived grid). */
  get enabled(): boolean {
    return this.#state.enabled;
  }

  get state(): PerceptionViewState {
    return structuredClone(this.#state);
  }

  #start(): void {
    this.#state = { enabled: true, looks: 0, objects: [], cells: { free: 0, occupied: 0 } };
    this.#for = undefined;
    this.#schedule(0);
  }

  #stop(): void {
    if (this.#timer !== undefined) clearTimeout(this.#timer);
    this.#timer = undefined;
    this.#state = { ...this.#state, enabled: false };
    this.#boxes.clear();
    this.#options.list.replaceChildren();
    this.#options.scene.setOccupancyGrid(undefined);
    this.#options.onOff();
  }

  #schedule(delayMs: number): void {
    this.#timer = setTimeout(() => void this.#lookOnce(), delayMs);
  }

  /** The perception of the robot and map now: a fresh one when either changed. */
  #perceptionNow(): { perception: Perception; grid: OccupancyGrid; camera: CameraModel } {
    const { hal } = this.#options;
    const robot = hal.robot.id;
    const map = hal.world.map;
    const camera = hal.getDeviceInfo().camera ?? { ...V1_CAMERA };
    if (
      this.#perception === undefined ||
      this.#grid === undefined ||
      this.#for?.robot !== robot ||
      this.#for.map !== map
    ) {
      this.#grid = emptyGridOf(map);
      this.#perception = new Perception(hal, { camera, grid: this.#grid });
      this.#for = { robot, map };
    }
    return { perception: this.#perception, grid: this.#grid, camera };
  }

  async #lookOnce(): Promise<void> {
    if (!this.#state.enabled) return;
    const { perception, grid, camera } = this.#perceptionNow();
    try {
      const look = await perception.look();
      if (!this.#state.enabled) return;
      this.#show(look, grid, camera);
    } catch (error) {
      this.#state = {
        ...this.#state,
        error: errorMessage(error),
      };
      this.#options.list.replaceChildren(
        make('li', { className: 'fail' }, `cannot look: ${this.#state.error}`),
      );
    }
    if (this.#state.enabled) this.#schedule(LOOK_EVERY_MS);
  }

  #show(look: Look, grid: OccupancyGrid, camera: CameraModel): void {
    this.#boxes.draw(look, camera);
    this.#options.scene.setOccupancyGrid(perceivedGridView(grid));
    const counts = grid.counts();
    const objects = look.objects.map((o) => ({
      label: o.label,
      bearingDeg: o.bearingDeg,
      distanceM: o.distanceM,
      x: o.world.x,
      y: o.world.y,
    }));
    this.#state = {
      enabled: true,
      looks: this.#state.looks + 1,
      objects,
      cells: { free: counts.free, occupied: counts.occupied },
    };
    const items = objects.map((o) =>
      make(
        'li',
        {},
        `${o.label}: ${o.bearingDeg >= 0 ? '+' : ''}${o.bearingDeg.toFixed(0)}°, ${o.distanceM.toFixed(2)} m, at (${o.x.toFixed(2)}, ${o.y.toFixed(2)})`,
      ),
    );
    this.#options.list.replaceChildren(
      ...(items.length > 0 ? items : [make('li', { className: 'muted' }, 'no objects in view')]),
    );
  }
}
