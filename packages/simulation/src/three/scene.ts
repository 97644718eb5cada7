import * as THREE from 'three';
import type { CameraOptions } from '../camera.js';
import type { SimRobot } from '../robot/sim-robot.js';
import type { World } from '../world.js';
import { addLights, buildArena } from './arena-model.js';
import {
  disposeOccupancyGridMesh,
  goalMarker,
  occupancyGridMesh,
  plannedPathLine,
} from './planning-overlays.js';
import type { OccupancyGridView } from './planning-overlays.js';
import { RangeRays } from './range-rays.js';
import { placeRobotCamera, RobotModel } from './robot-model.js';
import { Trail } from './trail.js';

/*
 * Draws a World with Three.js: the arena, walls and obstacles, every robot, their pose trails, a
 * planned path, a goal marker and an occupancy grid. It only reads the world; the simulation runs
 * without it. World frame REP-103 (x forward, y left, z up) maps to Three's (x, z, -y), y up.
 */

export interface WorldSceneOptions {
  /** Most trail points kept per robot. Default 5000. */
  trailLength?: number;
  /** Colours of robots by index (cycled). */
  robotColors?: readonly string[];
  /**
   * A robot's colour by its id, for colours that stay with a robot when others are added or
   * removed; `undefined` falls back to `robotColors` by index.
   */
  robotColor?: (robotId: string) => string | undefined;
  /** Cast shadows. Default true. */
  shadows?: boolean;
  /** Draw each robot's range-sensor rays (front, diagonals, sides) up to what they hit. Default false. */
  showRangeRays?: boolean;
  /** Range of the drawn rays, metres. Default 2 (the default sensor range). */
  rangeRayLength?: number;
}

/** What the scene draws for one robot. */
interface RobotView {
  model: RobotModel;
  trail: Trail;
  rays: RangeRays | undefined;
}

/** The Three.js scene of a world. Call {@link update} once per frame. */
export class WorldScene {
  readonly scene = new THREE.Scene();
  readonly world: World;
  readonly #options: Required<Omit<WorldSceneOptions, 'robotColor'>>;
  readonly #robotColor: ((robotId: string) => string | undefined) | undefined;
  readonly #static = new THREE.Group();
  readonly #robots = new Map<string, RobotView>();
  readonly #overlays = new THREE.Group();
  #path: THREE.Line | undefined;
  #goal: THREE.Group | undefined;
  #grid: THREE.Mesh | undefined;
  #robotsVisible = true;
  /** Each robot's pose and LED as last drawn: an unchanged robot is not followed again. */
  readonly #drawn = new Map<string, string>();
  #revision = 0;
  readonly #unsubscribe: Array<() => void> = [];

  constructor(world: World, options: WorldSceneOptions = {}) {
    this.world = world;
    this.#options = {
      trailLength: options.trailLength ?? 5000,
      robotColors: options.robotColors ?? ['#f4b400', '#4285f4', '#db4437', '#0f9d58', '#ab47bc'],
      shadows: options.shadows ?? true,
      showRangeRays: options.showRangeRays ?? false,
      rangeRayLength: options.rangeRayLength ?? 2,
    };
    this.#robotColor = options.robotColor;
    this.scene.background = new THREE.Color('#dfe7f1');
    this.scene.fog = new THREE.Fog('#dfe7f1', 12, 30);
    addLights(this.scene, this.#options.shadows);
    this.scene.add(this.#static, this.#overlays);
    this.#buildStatic();
    this.#unsubscribe.push(
      world.events.on('map', () => {
        this.#buildStatic();
        this.#resetRobots();
      }),
      world.events.on('robots', () => this.#resetRobots()),
    );
    this.#resetRobots();
  }

  /**
   * Counts the changes to what the scene shows: a robot that moved or changed its LED, a path,
   * goal, grid or map set, trails cleared, robots shown or hidden. A view that drew the scene at
   * one revision need not draw it again until the revision changes (render on demand).
   */
  get revision(): number {
    return this.#revision;
  }

  /** Moves every robot's model to its pose, extends trails, lights LEDs (only what changed). */
  update(): void {
    let moved = false;
    for (const robot of this.world.robots) {
      let view = this.#robots.get(robot.id);
      if (view === undefined) {
        view = this.#addRobot(robot, this.#robots.size);
        this.#robots.set(robot.id, view);
      }
      const led = robot.led;
      const drawn = `${robot.x} ${robot.y} ${robot.yaw} ${led.pattern} ${led.r} ${led.g} ${led.b}`;
      if (this.#drawn.get(robot.id) === drawn) continue;
      this.#drawn.set(robot.id, drawn);
      moved = true;
      view.model.follow(robot);
      view.trail.follow(robot.x, robot.y);
    }
    if (!moved) return;
    this.#revision += 1;
    // every robot's rays: they stop at the other robots too
    for (const robot of this.world.robots)
      this.#robots.get(robot.id)?.rays?.follow(this.world, robot);
  }

  /**
   * Whether the overlays (trails, planned path, goal, occupancy grid, sensor rays) are drawn.
   * The robot's camera view turns them off while it renders: they are not in the robot's world.
   * (A toggle for one view's render, so it does not count as a change of the scene.)
   */
  get overlaysVisible(): boolean {
    return this.#overlays.visible;
  }
  set overlaysVisible(visible: boolean) {
    this.#overlays.visible = visible;
  }

  /**
   * Whether the world's robots (their models, trails and rays) are drawn. The demo hides them
   * while it plays a recording back in the same arena.
   */
  get robotsVisible(): boolean {
    return this.#robotsVisible;
  }
  set robotsVisible(visible: boolean) {
    if (visible !== this.#robotsVisible) this.#revision += 1;
    this.#robotsVisible = visible;
    for (const view of this.#robots.values()) this.#showRobot(view);
  }

  /** Clears every robot's trail. */
  clearTrails(): void {
    this.#revision += 1;
    for (const view of this.#robots.values()) view.trail.clear();
  }

  /** Draws a planned path (world points, metres), or removes it. */
  setPlannedPath(points: ReadonlyArray<{ x: number; y: number }> | undefined): void {
    this.#revision += 1;
    if (this.#path !== undefined) {
      this.#overlays.remove(this.#path);
      this.#path.geometry.dispose();
      this.#path = undefined;
    }
    if (points === undefined || points.length < 2) return;
    this.#path = plannedPathLine(points);
    this.#overlays.add(this.#path);
  }

  /** Shows a goal marker at a world point, or removes it. */
  setGoal(goal: { x: number; y: number } | undefined): void {
    this.#revision += 1;
    if (this.#goal !== undefined) this.#overlays.remove(this.#goal);
    this.#goal = undefined;
    if (goal === undefined) return;
    this.#goal = goalMarker(goal);
    this.#overlays.add(this.#goal);
  }

  /** Overlays an occupancy grid on the floor, or removes it. */
  setOccupancyGrid(grid: OccupancyGridView | undefined): void {
    this.#revision += 1;
    if (this.#grid !== undefined) {
      this.#overlays.remove(this.#grid);
      disposeOccupancyGridMesh(this.#grid);
      this.#grid = undefined;
    }
    if (grid === undefined) return;
    this.#grid = occupancyGridMesh(grid);
    this.#overlays.add(this.#grid);
  }

  /**
   * A camera at `robot`'s camera pose, looking where it looks (for the robot's view). Reuses
   * and updates `into` when given.
   */
  robotCamera(
    robot: SimRobot,
    options: CameraOptions = {},
    into?: THREE.PerspectiveCamera,
  ): THREE.PerspectiveCamera {
    return placeRobotCamera(robot, options, into);
  }

  /** Stops listening to the world and frees GPU resources. */
  dispose(): void {
    for (const off of this.#unsubscribe.splice(0)) off();
    this.scene.traverse((o) => {
      if (o instanceof THREE.Mesh || o instanceof THREE.Line) {
        o.geometry.dispose();
        const m = o.material as THREE.Material | THREE.Material[];
        for (const mat of Array.isArray(m) ? m : [m]) mat.dispose();
      }
    });
  }

  // ---- building ---------------------------------------------------------------------------

  #buildStatic(): void {
    this.#revision += 1;
    buildArena(this.#static, this.world, this.#options.shadows);
  }

  #resetRobots(): void {
    for (const view of this.#robots.values()) {
      this.#overlays.remove(view.trail.line);
      view.trail.dispose();
      if (view.rays !== undefined) {
        this.#overlays.remove(view.rays.lines);
        view.rays.dispose();
      }
      this.scene.remove(view.model.group);
    }
    this.#robots.clear();
    this.#drawn.clear();
    this.#revision += 1;
    this.world.robots.forEach((robot, i) => {
      this.#robots.set(robot.id, this.#addRobot(robot, i));
    });
    this.update();
  }

  /** Adds robot number `index`'s model to the scene, its trail and rays to the overlays. */
  #addRobot(robot: SimRobot, index: number): RobotView {
    const colors = this.#options.robotColors;
    const color = this.#robotColor?.(robot.id) ?? colors[index % colors.length] ?? '#f4b400';
    const model = new RobotModel(robot, color, this.#options.shadows);
    this.scene.add(model.group);
    const trail = new Trail(this.#options.trailLength, color, robot.x, robot.y);
    this.#overlays.add(trail.line);
    let rays: RangeRays | undefined;
    if (this.#options.showRangeRays) {
      rays = new RangeRays(this.#options.rangeRayLength);
      this.#overlays.add(rays.lines);
    }
    const view = { model, trail, rays };
    this.#showRobot(view);
    return view;
  }

  #showRobot(view: RobotView): void {
    view.model.group.visible = this.#robotsVisible;
    view.trail.line.visible = this.#robotsVisible;
    if (view.rays !== undefined) view.rays.lines.visible = this.#robotsVisible;
  }
}
