import * as THREE from 'three';
import { toThree } from './coordinates.js';

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

/** A planned path (world points, metres) as a dashed line just above the floor. */
export function plannedPathLine(points: ReadonlyArray<{ x: number; y: number }>): THREE.Line {
  const geometry = new THREE.BufferGeometry().setFromPoints(
    points.map((p) => toThree(p.x, p.y, 0.012)),
  );
  const line = new THREE.Line(
    geometry,
    new THREE.LineDashedMaterial({ color: '#1565c0', dashSize: 0.08, gapSize: 0.05 }),
  );
  line.computeLineDistances();
  return line;
}

/** A goal marker at a world point: a ring on the floor and a flag on a pole. */
export function goalMarker(goal: { x: number; y: number }): THREE.Group {
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
  return group;
}

/** An occupancy grid as a translucent texture on the floor. */
export function occupancyGridMesh(grid: OccupancyGridView): THREE.Mesh {
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
  return mesh;
}

/** Frees what {@link occupancyGridMesh} allocated (geometry and texture). */
export function disposeOccupancyGridMesh(mesh: THREE.Mesh): void {
  mesh.geometry.dispose();
  (mesh.material as THREE.MeshBasicMaterial).map?.dispose();
}
