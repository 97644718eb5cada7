import * as THREE from 'three';
import type { Solid } from '../shapes.js';
import type { World } from '../world.js';
import { threeColor, toThree } from './coordinates.js';

/** Lights the scene: a sky/ground hemisphere and a sun that casts shadows when asked to. */
export function addLights(scene: THREE.Scene, shadows: boolean): void {
  scene.add(new THREE.HemisphereLight('#ffffff', '#8d8a80', 1.25));
  const sun = new THREE.DirectionalLight('#ffffff', 1.6);
  sun.position.set(-3, 6, 4);
  sun.castShadow = shadows;
  sun.shadow.mapSize.set(2048, 2048);
  const s = sun.shadow.camera;
  s.left = -6;
  s.right = 6;
  s.top = 6;
  s.bottom = -6;
  scene.add(sun);
}

/**
 * Fills `group` (emptied first) with the world's static part: the arena floor with a 0.5 m grid,
 * the ground around it, and every wall and obstacle of the map.
 */
export function buildArena(group: THREE.Group, world: World, shadows: boolean): void {
  group.clear();
  const { arena } = world.map;
  const floor = new THREE.Mesh(
    new THREE.PlaneGeometry(arena.width, arena.height),
    new THREE.MeshStandardMaterial({ color: '#f3efe6', roughness: 0.95 }),
  );
  floor.rotation.x = -Math.PI / 2;
  floor.receiveShadow = shadows;
  group.add(floor);
  const ground = new THREE.Mesh(
    new THREE.PlaneGeometry(arena.width + 40, arena.height + 40),
    new THREE.MeshStandardMaterial({ color: '#c9d3de', roughness: 1 }),
  );
  ground.rotation.x = -Math.PI / 2;
  ground.position.y = -0.002;
  ground.receiveShadow = shadows;
  group.add(ground);
  const size = Math.max(arena.width, arena.height);
  const divisions = Math.round(size / 0.5);
  const grid = new THREE.GridHelper(size, divisions, '#a39a86', '#c9c0ad');
  grid.position.y = 0.001;
  grid.scale.set(arena.width / size, 1, arena.height / size);
  group.add(grid);
  for (const solid of world.solids) group.add(solidMesh(solid, shadows));
}

/** A wall or obstacle: a box or an upright cylinder in its colour. */
function solidMesh(solid: Solid, shadows: boolean): THREE.Mesh {
  const material = new THREE.MeshStandardMaterial({
    color: threeColor(solid.color),
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
  mesh.castShadow = shadows;
  mesh.receiveShadow = shadows;
  return mesh;
}
