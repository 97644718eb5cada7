import type { SimRobot, World } from '@hal/simulation';
import { fromThree, toThree } from '@hal/simulation/three';
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { RenderProfile } from './render-profile.js';

/** A press that moves further than this before release is a drag (it orbits), not a click, px. */
const CLICK_SLOP_PX = 5;

/**
 * The 3D view of the arena: a WebGL canvas in `container` with an orbiting camera (drag to
 * orbit, scroll to zoom), framing the whole arena or following the robot, and clicks on the floor.
 */
export class Viewport {
  readonly renderer: THREE.WebGLRenderer;
  readonly camera = new THREE.PerspectiveCamera(45, 1, 0.05, 200);
  readonly controls: OrbitControls;
  readonly #container: HTMLElement;
  readonly #world: World;
  readonly #robot: () => SimRobot;
  /** Where the followed robot was last frame (Three coordinates); undefined: not following. */
  #followed: THREE.Vector3 | undefined;
  /** The camera or the canvas changed since the last frame drawn. */
  #moved = true;
  /** What {@link onResized} was given, called in order. */
  readonly #resized: (() => void)[] = [];

  constructor(
    container: HTMLElement,
    world: World,
    robot: () => SimRobot,
    profile: Pick<RenderProfile, 'antialias' | 'shadows' | 'pixelRatio'>,
  ) {
    this.#container = container;
    this.#world = world;
    this.#robot = robot;
    const renderer = new THREE.WebGLRenderer({ antialias: profile.antialias });
    renderer.setPixelRatio(profile.pixelRatio);
    renderer.shadowMap.enabled = profile.shadows;
    renderer.shadowMap.type = THREE.PCFShadowMap;
    container.prepend(renderer.domElement);
    this.renderer = renderer;
    const controls = new OrbitControls(this.camera, renderer.domElement);
    controls.enableDamping = true;
    controls.maxPolarAngle = Math.PI / 2 - 0.05;
    controls.minDistance = 0.4;
    controls.maxDistance = 25;
    this.controls = controls;
    controls.addEventListener('change', () => (this.#moved = true));
    this.frameArena();
    this.#resize();
    new ResizeObserver(() => {
      this.#resize();
      for (const listener of this.#resized) listener();
    }).observe(container);
  }

  /**
   * Calls `redraw` each time the canvas takes the size of its container, right after, in the same
   * rendering step. A canvas that takes a new size is cleared, and the browser shows it as it is at
   * the end of that step: a frame left to the next animation frame leaves the view blank for one
   * frame, and that frame is the one a headless screenshot captures (Chromium sizes the page to the
   * window just before it takes the picture). So `redraw` draws the view at once.
   */
  onResized(redraw: () => void): void {
    this.#resized.push(redraw);
  }

  /** Looks at the whole arena from its south side. */
  frameArena(): void {
    const { width, height } = this.#world.map.arena;
    const size = Math.max(width, height);
    this.camera.position.copy(toThree(-size * 0.05, -size * 0.95, size * 1.05));
    this.controls.target.set(0, 0, 0);
    this.controls.update();
  }

  /** "Follow robot": rides along behind the robot (true), or frames the arena again (false). */
  follow(on: boolean): void {
    if (!on) {
      this.#followed = undefined;
      this.frameArena();
      return;
    }
    // Close behind the robot, looking where it goes; then keep that offset as it moves.
    const robot = this.#robot();
    this.#followed = toThree(robot.x, robot.y);
    this.controls.target.copy(this.#followed);
    this.camera.position.copy(
      toThree(robot.x - 0.9 * Math.cos(robot.yaw), robot.y - 0.9 * Math.sin(robot.yaw), 0.6),
    );
    this.controls.update();
  }

  /**
   * Moves the camera along with a followed robot and on with the orbit's damping. True when the
   * view changed since the last frame drawn (the camera moved, or the canvas was resized).
   */
  update(): boolean {
    this.#keepFollowing();
    this.controls.update(); // a change it makes is reported by its 'change' event
    return this.#moved;
  }

  /** Draws a frame of `scene` from the camera. */
  render(scene: THREE.Scene): void {
    this.#moved = false;
    this.renderer.render(scene, this.camera);
  }

  /** Calls `handler` with the world point (metres) of every click on the floor. */
  onFloorClick(handler: (point: { x: number; y: number }) => void): void {
    const canvas = this.renderer.domElement;
    const floor = new THREE.Plane(new THREE.Vector3(0, 1, 0), 0);
    const raycaster = new THREE.Raycaster();
    let pressedAt: { x: number; y: number } | undefined;
    canvas.addEventListener('pointerdown', (e) => {
      pressedAt = { x: e.clientX, y: e.clientY };
    });
    canvas.addEventListener('pointerup', (e) => {
      if (pressedAt === undefined || e.button !== 0) return;
      const moved = Math.hypot(e.clientX - pressedAt.x, e.clientY - pressedAt.y);
      pressedAt = undefined;
      if (moved > CLICK_SLOP_PX) return; // a drag orbits the view
      const rect = canvas.getBoundingClientRect();
      const ndc = new THREE.Vector2(
        ((e.clientX - rect.left) / rect.width) * 2 - 1,
        -((e.clientY - rect.top) / rect.height) * 2 + 1,
      );
      raycaster.setFromCamera(ndc, this.camera);
      const hit = raycaster.ray.intersectPlane(floor, new THREE.Vector3());
      if (hit === null) return;
      handler(fromThree(hit));
    });
  }

  /** Where a world point (metres; z above the floor) is on the screen, in client pixels. */
  worldToClient(x: number, y: number, z = 0): { x: number; y: number } {
    const p = toThree(x, y, z).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return {
      x: rect.left + ((p.x + 1) / 2) * rect.width,
      y: rect.top + ((1 - p.y) / 2) * rect.height,
    };
  }

  #keepFollowing(): void {
    if (this.#followed === undefined) return;
    const robot = this.#robot();
    const now = toThree(robot.x, robot.y);
    const delta = now.clone().sub(this.#followed);
    if (delta.lengthSq() === 0) return;
    this.#moved = true;
    this.camera.position.add(delta);
    this.controls.target.add(delta);
    this.#followed = now;
  }

  #resize(): void {
    const { clientWidth: w, clientHeight: h } = this.#container;
    this.renderer.setSize(w, h, false);
    this.renderer.domElement.style.width = `${w}px`;
    this.renderer.domElement.style.height = `${h}px`;
    this.camera.aspect = w / Math.max(h, 1);
    this.camera.updateProjectionMatrix();
    this.#moved = true;
  }
}
