import * as THREE from 'three';
import { cameraPose } from '../camera.js';
import type { CameraOptions } from '../camera.js';
import { rangeAlong } from '../sensors.js';
import type { SimRobot } from '../robot.js';
import type { Rgb, Solid } from '../shapes.js';
import type { World } from '../world.js';

/*
 * Draws a World with Three.js: the arena, walls and obstacles, every robot, their pose trails, a
 * planned path, a goal marker and an occupancy grid. It only reads the world; the simulation runs
 * without it. World frame REP-103 (x forward, y left, z up) maps to Three's (x, z, -y), y up.
 */

/** An occupancy grid to overlay on the floor: cells row by row from `origin`, +x then +y. */
export interface OccupancyGridView {
  /** Cells along x. */
  width: number;
  /** Cells along y. */
  height: number;
  /** Cell side, metres. */
  resolution: number;
  /** World position of the corner of cell (0, 0), metres. */
  origin: { x: number; y: number };
  /** Occupancy per cell, 0 (free) .. 1 (occupied); negative: unknown. Drawn: above 0.5 red, unknown blue haze, free clear. */
  data: ArrayLike<number>;
}

export interface WorldSceneOptions {
  /** Most trail points kept per robot. Default 5000. */
  trailLength?: number;
  /** Colours of robots by index (cycled). */
  robotColors?: readonly string[];
  /** Cast shadows. Default true. */
  shadows?: boolean;
  /** Draw each robot's range-sensor rays (front, diagonals, sides) up to what they hit. Default false. */
  showRangeRays?: boolean;
  /** Range of the drawn rays, metres. Default 2 (the default sensor range). */
  rangeRayLength?: number;
}

/** World (x, y, z) in metres to a Three.js position. */
export function toThree(x: number, y: number, z = 0): THREE.Vector3 {
  return new THREE.Vector3(x, z, -y);
}

/** A Three.js position to world (x, y, z), metres. */
export function fromThree(v: THREE.Vector3): { x: number; y: number; z: number } {
  return { x: v.x, y: -v.z, z: v.y };
}

const colorOf = (c: Rgb) => new THREE.Color(c.r / 255, c.g / 255, c.b / 255);

const RAY_ANGLES = [0, Math.PI / 4, -Math.PI / 4, Math.PI / 2, -Math.PI / 2];

interface RobotView {
  group: THREE.Group;
  rays: THREE.LineSegments | undefined;
  led: THREE.MeshStandardMaterial;
  trail: THREE.Line;
  trailPositions: Float32Array;
  trailCount: number;
  lastX: number;
  lastY: number;
}

/** The Three.js scene of a world. Call {@link update} once per frame. */
export class WorldScene {
  readonly scene = new THREE.Scene();
  readonly world: World;
  readonly #options: Required<WorldSceneOptions>;
  readonly #static = new THREE.Group();
  readonly #robots = new Map<string, RobotView>();
  readonly #overlays = new THREE.Group();
  #path: THREE.Line | undefined;
  #goal: THREE.Group | undefined;
  #grid: THREE.Mesh | undefined;
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
    this.scene.background = new THREE.Color('#dfe7f1');
    this.scene.fog = new THREE.Fog('#dfe7f1', 12, 30);
    const hemi = new THREE.HemisphereLight('#ffffff', '#8d8a80', 1.25);
    this.scene.add(hemi);
    const sun = new THREE.DirectionalLight('#ffffff', 1.6);
    sun.position.set(-3, 6, 4);
    sun.castShadow = this.#options.shadows;
    sun.shadow.mapSize.set(2048, 2048);
    const s = sun.shadow.camera;
    s.left = -6;
    s.right = 6;
    s.top = 6;
    s.bottom = -6;
    this.scene.add(sun);
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

  /** Moves every robot's model to its pose, extends trails, lights LEDs. */
  update(): void {
    for (const robot of this.world.robots) {
      let view = this.#robots.get(robot.id);
      if (view === undefined) {
        view = this.#makeRobot(robot, this.#robots.size);
        this.#robots.set(robot.id, view);
      }
      view.group.position.copy(toThree(robot.x, robot.y));
      view.group.rotation.y = robot.yaw;
      const led = robot.led;
      const on = led.pattern !== 'off' && (led.r > 0 || led.g > 0 || led.b > 0);
      view.led.emissive.setRGB(
        on ? led.r / 255 : 0.05,
        on ? led.g / 255 : 0.05,
        on ? led.b / 255 : 0.05,
      );
      if (view.rays !== undefined) this.#updateRays(view.rays, robot);
      if (Math.hypot(robot.x - view.lastX, robot.y - view.lastY) > 0.005 || view.trailCount === 0) {
        this.#pushTrail(view, robot.x, robot.y);
      }
    }
  }

  /**
   * Whether the overlays (trails, planned path, goal, occupancy grid, sensor rays) are drawn.
   * The robot's camera view turns them off while it renders: they are not in the robot's world.
   */
  get overlaysVisible(): boolean {
    return this.#overlays.visible;
  }
  set overlaysVisible(visible: boolean) {
    this.#overlays.visible = visible;
  }

  /** Clears every robot's trail. */
  clearTrails(): void {
    for (const view of this.#robots.values()) {
      view.trailCount = 0;
      view.trail.geometry.setDrawRange(0, 0);
    }
  }

  /** Draws a planned path (world points, metres), or removes it. */
  setPlannedPath(points: ReadonlyArray<{ x: number; y: number }> | undefined): void {
    if (this.#path !== undefined) {
      this.#overlays.remove(this.#path);
      this.#path.geometry.dispose();
      this.#path = undefined;
    }
    if (points === undefined || points.length < 2) return;
    const geometry = new THREE.BufferGeometry().setFromPoints(
      points.map((p) => toThree(p.x, p.y, 0.012)),
    );
    const line = new THREE.Line(
      geometry,
      new THREE.LineDashedMaterial({ color: '#1565c0', dashSize: 0.08, gapSize: 0.05 }),
    );
    line.computeLineDistances();
    this.#path = line;
    this.#overlays.add(line);
  }

  /** Shows a goal marker at a world point, or removes it. */
  setGoal(goal: { x: number; y: number } | undefined): void {
    if (this.#goal !== undefined) this.#overlays.remove(this.#goal);
    this.#goal = undefined;
    if (goal === undefined) return;
    const group = new THREE.Group();
    const ring = new THREE.Mesh(
      new THREE.RingGeometry(0.07, 0.1, 40),
      new THREE.MeshBasicMaterial({ color: '#d81b60', side: THREE.DoubleSide }),
    );
    ring.rotation.x = -Math.PI / 2;
    ring.position.y = 0.004;
    const pole = new THREE.Mesh(
      new THREE.CylinderGeometry(0.006, 0.006, 0.3, 8),
      new THREE.MeshStandardMaterial({ color: '#880e4f' }),
    );
    pole.position.y = 0.15;
    const flag = new THREE.Mesh(
      new THREE.BoxGeometry(0.09, 0.06, 0.004),
      new THREE.MeshStandardMaterial({ color: '#d81b60' }),
    );
    flag.position.set(0.045, 0.27, 0);
    group.add(ring, pole, flag);
    group.position.copy(toThree(goal.x, goal.y));
    this.#goal = group;
    this.#overlays.add(group);
  }

  /** Overlays an occupancy grid on the floor, or removes it. */
  setOccupancyGrid(grid: OccupancyGridView | undefined): void {
    if (this.#grid !== undefined) {
      this.#overlays.remove(this.#grid);
      this.#grid.geometry.dispose();
      (this.#grid.material as THREE.MeshBasicMaterial).map?.dispose();
      this.#grid = undefined;
    }
    if (grid === undefined) return;
    const pixels = new Uint8Array(grid.width * grid.height * 4);
    for (let i = 0; i < grid.width * grid.height; i += 1) {
      const v = grid.data[i] ?? -1;
      const o = i * 4;
      if (v < 0) {
        pixels.set([90, 110, 150, 40], o); // unknown: a faint blue haze
      } else if (v > 0.5) {
        pixels.set([150, 30, 50, Math.round(60 + (v - 0.5) * 2 * 140)], o); // occupied
      } else {
        pixels.set([0, 0, 0, 0], o); // free
      }
    }
    const texture = new THREE.DataTexture(pixels, grid.width, grid.height);
    texture.magFilter = THREE.NearestFilter;
    texture.needsUpdate = true;
    const w = grid.width * grid.resolution;
    const h = grid.height * grid.resolution;
    const mesh = new THREE.Mesh(
      new THREE.PlaneGeometry(w, h),
      new THREE.MeshBasicMaterial({ map: texture, transparent: true, depthWrite: false }),
    );
    // Texture rows go +y in the world (the plane's +v after the rotation below).
    mesh.rotation.x = -Math.PI / 2;
    mesh.position.copy(toThree(grid.origin.x + w / 2, grid.origin.y + h / 2, 0.003));
    this.#grid = mesh;
    this.#overlays.add(mesh);
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
    const width = options.width ?? 320;
    const height = options.height ?? 240;
    const hfov = ((options.fieldOfViewDeg ?? 62) * Math.PI) / 180;
    const vfov = 2 * Math.atan(Math.tan(hfov / 2) * (height / width));
    const camera = into ?? new THREE.PerspectiveCamera(1, 1, 0.01, 40);
    camera.fov = (vfov * 180) / Math.PI;
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    const pose = cameraPose(robot, options);
    camera.position.copy(toThree(pose.x, pose.y, pose.z));
    camera.lookAt(toThree(pose.x + Math.cos(pose.yaw), pose.y + Math.sin(pose.yaw), pose.z));
    return camera;
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
    this.#static.clear();
    const { arena } = this.world.map;
    const floor = new THREE.Mesh(
      new THREE.PlaneGeometry(arena.width, arena.height),
      new THREE.MeshStandardMaterial({ color: '#f3efe6', roughness: 0.95 }),
    );
    floor.rotation.x = -Math.PI / 2;
    floor.receiveShadow = this.#options.shadows;
    this.#static.add(floor);
    const ground = new THREE.Mesh(
      new THREE.PlaneGeometry(arena.width + 40, arena.height + 40),
      new THREE.MeshStandardMaterial({ color: '#c9d3de', roughness: 1 }),
    );
    ground.rotation.x = -Math.PI / 2;
    ground.position.y = -0.002;
    ground.receiveShadow = this.#options.shadows;
    this.#static.add(ground);
    const size = Math.max(arena.width, arena.height);
    const divisions = Math.round(size / 0.5);
    const grid = new THREE.GridHelper(size, divisions, '#a39a86', '#c9c0ad');
    grid.position.y = 0.001;
    grid.scale.set(arena.width / size, 1, arena.height / size);
    this.#static.add(grid);
    for (const solid of this.world.solids) this.#static.add(this.#solidMesh(solid));
  }

  #solidMesh(solid: Solid): THREE.Mesh {
    const material = new THREE.MeshStandardMaterial({
      color: colorOf(solid.color),
      roughness: 0.7,
      metalness: 0.05,
    });
    let mesh: THREE.Mesh;
    if (solid.kind === 'box') {
      const w = solid.maxX - solid.minX;
      const d = solid.maxY - solid.minY;
      mesh = new THREE.Mesh(new THREE.BoxGeometry(w, solid.height, d), material);
      mesh.position.copy(
        toThree((solid.minX + solid.maxX) / 2, (solid.minY + solid.maxY) / 2, solid.height / 2),
      );
    } else {
      mesh = new THREE.Mesh(
        new THREE.CylinderGeometry(solid.radius, solid.radius, solid.height, 40),
        material,
      );
      mesh.position.copy(toThree(solid.x, solid.y, solid.height / 2));
    }
    mesh.castShadow = this.#options.shadows;
    mesh.receiveShadow = this.#options.shadows;
    return mesh;
  }

  #resetRobots(): void {
    for (const view of this.#robots.values()) {
      this.#overlays.remove(view.trail);
      view.trail.geometry.dispose();
      if (view.rays !== undefined) {
        this.#overlays.remove(view.rays);
        view.rays.geometry.dispose();
      }
      this.scene.remove(view.group);
    }
    this.#robots.clear();
    this.world.robots.forEach((robot, i) => {
      this.#robots.set(robot.id, this.#makeRobot(robot, i));
    });
    this.update();
  }

  #makeRobot(robot: SimRobot, index: number): RobotView {
    const colors = this.#options.robotColors;
    const color = colors[index % colors.length] ?? '#f4b400';
    const group = new THREE.Group();
    const side = robot.radius * Math.SQRT2 * 0.95;
    const body = new THREE.Mesh(
      new THREE.BoxGeometry(side, 0.085, side),
      new THREE.MeshStandardMaterial({ color, roughness: 0.45, metalness: 0.1 }),
    );
    body.position.y = 0.05;
    body.castShadow = this.#options.shadows;
    group.add(body);
    const wheelMaterial = new THREE.MeshStandardMaterial({ color: '#263238', roughness: 0.9 });
    for (const sideSign of [1, -1]) {
      const wheel = new THREE.Mesh(
        new THREE.CylinderGeometry(0.03, 0.03, 0.012, 24),
        wheelMaterial,
      );
      wheel.rotation.x = Math.PI / 2;
      wheel.position.set(0, 0.03, sideSign * (side / 2 + 0.007));
      wheel.castShadow = this.#options.shadows;
      group.add(wheel);
    }
    const lens = new THREE.Mesh(
      new THREE.BoxGeometry(0.012, 0.025, 0.03),
      new THREE.MeshStandardMaterial({ color: '#111111', roughness: 0.2 }),
    );
    lens.position.set(side / 2 + 0.006, 0.075, 0);
    group.add(lens);
    const arrow = new THREE.Mesh(
      new THREE.ConeGeometry(0.018, 0.04, 3),
      new THREE.MeshStandardMaterial({ color: '#37474f' }),
    );
    arrow.rotation.z = -Math.PI / 2;
    arrow.position.set(side / 4, 0.094, 0);
    group.add(arrow);
    const led = new THREE.MeshStandardMaterial({ color: '#222222', emissive: '#111111' });
    const ledMesh = new THREE.Mesh(new THREE.SphereGeometry(0.01, 16, 8), led);
    ledMesh.position.set(-side / 4, 0.097, 0);
    group.add(ledMesh);
    this.scene.add(group);

    const capacity = this.#options.trailLength;
    const trailPositions = new Float32Array(capacity * 3);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(trailPositions, 3));
    geometry.setDrawRange(0, 0);
    const trail = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
    trail.frustumCulled = false;
    this.#overlays.add(trail);
    let rays: THREE.LineSegments | undefined;
    if (this.#options.showRangeRays) {
      const rayGeometry = new THREE.BufferGeometry();
      rayGeometry.setAttribute(
        'position',
        new THREE.BufferAttribute(new Float32Array(RAY_ANGLES.length * 6), 3),
      );
      rays = new THREE.LineSegments(
        rayGeometry,
        new THREE.LineBasicMaterial({ color: '#e53935', transparent: true, opacity: 0.55 }),
      );
      rays.frustumCulled = false;
      this.#overlays.add(rays);
    }
    return {
      group,
      rays,
      led,
      trail,
      trailPositions,
      trailCount: 0,
      lastX: robot.x,
      lastY: robot.y,
    };
  }

  #updateRays(rays: THREE.LineSegments, robot: SimRobot): void {
    const attr = rays.geometry.getAttribute('position') as THREE.BufferAttribute;
    const h = 0.06;
    RAY_ANGLES.forEach((offset, i) => {
      const angle = robot.yaw + offset;
      const hit = rangeAlong(this.world, robot, angle, this.#options.rangeRayLength);
      const from = robot.radius;
      const to = robot.radius + hit.distance;
      const c = Math.cos(angle);
      const sn = Math.sin(angle);
      attr.setXYZ(i * 2, robot.x + c * from, h, -(robot.y + sn * from));
      attr.setXYZ(i * 2 + 1, robot.x + c * to, h, -(robot.y + sn * to));
    });
    attr.needsUpdate = true;
  }

  #pushTrail(view: RobotView, x: number, y: number): void {
    const capacity = this.#options.trailLength;
    if (view.trailCount >= capacity) {
      view.trailPositions.copyWithin(0, 3);
      view.trailCount = capacity - 1;
    }
    const o = view.trailCount * 3;
    view.trailPositions[o] = x;
    view.trailPositions[o + 1] = 0.008;
    view.trailPositions[o + 2] = -y;
    view.trailCount += 1;
    view.lastX = x;
    view.lastY = y;
    const attr = view.trail.geometry.getAttribute('position') as THREE.BufferAttribute;
    attr.needsUpdate = true;
    view.trail.geometry.setDrawRange(0, view.trailCount);
  }
}
