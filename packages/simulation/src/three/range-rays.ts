import * as THREE from 'three';
import type { SimRobot } from '../robot/sim-robot.js';
import { rangeAlong } from '../sensors.js';
import type { World } from '../world.js';

/** The range sensors' directions from the heading: front, front-left, front-right, left, right. */
const RAY_ANGLES = [0, Math.PI / 4, -Math.PI / 4, Math.PI / 2, -Math.PI / 2];
/** Height the rays are drawn at, metres. */
const RAY_HEIGHT = 0.06;

/** A robot's range-sensor rays, drawn from the body's edge up to what each one hits. */
export class RangeRays {
  readonly lines: THREE.LineSegments;
  readonly #length: number;

  /** `length`: the range of the drawn rays, metres. */
  constructor(length: number) {
    this.#length = length;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute(
      'position',
      new THREE.BufferAttribute(new Float32Array(RAY_ANGLES.length * 6), 3),
    );
    this.lines = new THREE.LineSegments(
      geometry,
      new THREE.LineBasicMaterial({ color: '#e53935', transparent: true, opacity: 0.55 }),
    );
    this.lines.frustumCulled = false;
  }

  /** Casts the rays from the robot's pose in `world` and redraws them. */
  follow(world: World, robot: SimRobot): void {
    const attr = this.lines.geometry.getAttribute('position') as THREE.BufferAttribute;
    RAY_ANGLES.forEach((offset, i) => {
      const angle = robot.yaw + offset;
      const hit = rangeAlong(world, robot, angle, this.#length);
      const from = robot.radius;
      const to = robot.radius + hit.distance;
      const c = Math.cos(angle);
      const sn = Math.sin(angle);
      attr.setXYZ(i * 2, robot.x + c * from, RAY_HEIGHT, -(robot.y + sn * from));
      attr.setXYZ(i * 2 + 1, robot.x + c * to, RAY_HEIGHT, -(robot.y + sn * to));
    });
    attr.needsUpdate = true;
  }

  dispose(): void {
    this.lines.geometry.dispose();
  }
}
