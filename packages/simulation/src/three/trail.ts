import * as THREE from 'three';

/** Height of a trail above the floor, metres. */
const TRAIL_HEIGHT = 0.008;
/** A trail gains a point when the robot has moved this far since the last one, metres. */
const TRAIL_STEP = 0.005;

/** The line a robot leaves on the floor: its last `capacity` positions, oldest dropped first. */
export class Trail {
  readonly line: THREE.Line;
  readonly #capacity: number;
  readonly #positions: Float32Array;
  #count = 0;
  #lastX: number;
  #lastY: number;

  constructor(capacity: number, color: string, x: number, y: number) {
    this.#capacity = capacity;
    this.#positions = new Float32Array(capacity * 3);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(this.#positions, 3));
    geometry.setDrawRange(0, 0);
    this.line = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
    this.line.frustumCulled = false;
    this.#lastX = x;
    this.#lastY = y;
  }

  /** Adds the robot's position (world, metres) if it has moved far enough or the trail is empty. */
  follow(x: number, y: number): void {
    if (Math.hypot(x - this.#lastX, y - this.#lastY) > TRAIL_STEP || this.#count === 0) {
      this.#push(x, y);
    }
  }

  clear(): void {
    this.#count = 0;
    this.line.geometry.setDrawRange(0, 0);
  }

  dispose(): void {
    this.line.geometry.dispose();
  }

  #push(x: number, y: number): void {
    if (this.#count >= this.#capacity) {
      this.#positions.copyWithin(0, 3);
      this.#count = this.#capacity - 1;
    }
    const o = this.#count * 3;
    this.#positions[o] = x;
    this.#positions[o + 1] = TRAIL_HEIGHT;
    this.#positions[o + 2] = -y;
    this.#count += 1;
    this.#lastX = x;
    this.#lastY = y;
    const attr = this.line.geometry.getAttribute('position') as THREE.BufferAttribute;
    attr.needsUpdate = true;
    this.line.geometry.setDrawRange(0, this.#count);
  }
}
