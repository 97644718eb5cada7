import * as THREE from 'three';
import type { Rgb } from '../shapes.js';

/*
 * World frame REP-103 (x forward, y left, z up) maps to Three's (x, z, -y), y up.
 */

/** World (x, y, z) in metres to a Three.js position. */
export function toThree(x: number, y: number, z = 0): THREE.Vector3 {
  return new THREE.Vector3(x, z, -y);
}

/** A Three.js position to world (x, y, z), metres. */
export function fromThree(v: THREE.Vector3): { x: number; y: number; z: number } {
  return { x: v.x, y: -v.z, z: v.y };
}

/** A map colour as a Three.js colour. */
export function threeColor(c: Rgb): THREE.Color {
  return new THREE.Color(c.r / 255, c.g / 255, c.b / 255);
}
