import { fromThree, toThree } from '@hal/simulation/three';
import * as THREE from 'three';
import type { TimedPose } from './timeline.js';

/** The V1 cube's body side (its 7 cm footprint radius, as the live model draws it), metres. */
const SIDE_M = 0.07 * Math.SQRT2 * 0.95;
const COLOR = '#7e57c2';

/**
 * The recorded robot in the 3D scene: a cube with its heading arrow at the pose being played
 * back, and the whole recorded path as a line on the floor.
 */
export class PlaybackRobot {
  readonly group = new THREE.Group();
  readonly #body = new THREE.Group();
  readonly #path: THREE.Line;

  constructor(poses: readonly TimedPose[]) {
    const body = new THREE.Mesh(
      new THREE.BoxGeometry(SIDE_M, 0.085, SIDE_M),
      new THREE.MeshStandardMaterial({ color: COLOR, roughness: 0.45, metalness: 0.1 }),
    );
    body.position.y = 0.05;
    body.castShadow = true;
    const arrow = new THREE.Mesh(
      new THREE.ConeGeometry(0.018, 0.04, 3),
      new THREE.MeshStandardMaterial({ color: '#311b92' }),
    );
    arrow.rotation.z = -Math.PI / 2;
    arrow.position.set(SIDE_M / 4, 0.094, 0);
    this.#body.add(body, arrow);
    const points = poses.map((p) => toThree(p.x, p.y, 0.004));
    this.#path = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(points),
      new THREE.LineBasicMaterial({ color: COLOR }),
    );
    this.group.add(this.#body, this.#path);
  }

  /** Puts the robot at `pose` (world metres and yaw), or hides it when there is none. */
  show(pose: { x: number; y: number; yaw: number } | undefined): void {
    this.#body.visible = pose !== undefined;
    if (pose === undefined) return;
    this.#body.position.copy(toThree(pose.x, pose.y));
    this.#body.rotation.y = pose.yaw;
  }

  /** Where the scene draws the robot now (world metres and yaw); undefined when hidden. */
  drawnPose(): { x: number; y: number; yaw: number } | undefined {
    if (!this.#body.visible) return undefined;
    const { x, y } = fromThree(this.#body.position);
    return { x, y, yaw: this.#body.rotation.y };
  }

  dispose(): void {
    this.group.traverse((o) => {
      if (o instanceof THREE.Mesh || o instanceof THREE.Line) {
        o.geometry.dispose();
        (o.material as THREE.Material).dispose();
      }
    });
  }
}
