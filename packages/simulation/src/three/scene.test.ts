import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { World } from '../world.js';
import { fromThree, toThree } from './coordinates.js';
import { WorldScene } from './scene.js';

function meshes(scene: THREE.Object3D): THREE.Mesh[] {
  const found: THREE.Mesh[] = [];
  scene.traverse((o) => {
    if (o instanceof THREE.Mesh) found.push(o);
  });
  return found;
}

describe('WorldScene', () => {
  it('maps the REP-103 world frame to Three (x, z, -y) and back', () => {
    expect(toThree(1, 2, 3).toArray()).toEqual([1, 3, -2]);
    expect(fromThree(new THREE.Vector3(1, 3, -2))).toEqual({ x: 1, y: 2, z: 3 });
  });

  it('draws every solid of the map and rebuilds when the map changes', () => {
    const world = new World({ map: 'obstacles' });
    const view = new WorldScene(world, { shadows: false });
    const count = () =>
      meshes(view.scene).filter((m) => m.geometry.type !== 'PlaneGeometry').length;
    const obstacles = count();
    world.setMap('empty');
    expect(count()).toBe(obstacles - 8); // 8 obstacles fewer, the same arena walls
    view.dispose();
  });

  it('puts each robot model at its pose, facing its heading, and extends its trail', () => {
    const world = new World();
    const robot = world.addRobot();
    const view = new WorldScene(world, { shadows: false });
    world.events.on('tick', () => view.update());
    robot.rotateDeg(90);
    world.advanceUntil(() => !robot.running, 10_000_000);
    robot.moveCm(20, 20);
    world.advanceUntil(() => !robot.running, 10_000_000);
    view.update();
    const camera = view.robotCamera(robot);
    const ahead = new THREE.Vector3();
    camera.getWorldDirection(ahead);
    // Facing +y in the world is facing -z in Three, looking down by the camera's 20 degree tilt
    // (Three's y is up).
    const tilt = (20 * Math.PI) / 180;
    expect(ahead.z).toBeCloseTo(-Math.cos(tilt), 3);
    expect(ahead.y).toBeCloseTo(-Math.sin(tilt), 3);
    expect(ahead.x).toBeCloseTo(0, 3);
    expect(fromThree(camera.position).y).toBeCloseTo(0.2 + 0.05, 2);
    const trail = view.scene.getObjectsByProperty('type', 'Line')[0] as THREE.Line;
    expect(trail.geometry.drawRange.count).toBeGreaterThan(10);
  });

  it('keeps a colour with its robot by id when another robot is removed', () => {
    const world = new World();
    world.addRobot({ id: 'a', start: { x: 0, y: 0, yaw: 0 } });
    world.addRobot({ id: 'b', start: { x: 0.5, y: 0, yaw: 0 } });
    world.addRobot({ id: 'c', start: { x: 1, y: 0, yaw: 0 } });
    const colors: Record<string, string> = { a: '#ff0000', b: '#00ff00' };
    const view = new WorldScene(world, { shadows: false, robotColor: (id) => colors[id] });
    /** The colours of the robots' bodies (boxes 8.5 cm tall), by x. */
    const bodies = () =>
      meshes(view.scene)
        .filter(
          (m) => m.geometry instanceof THREE.BoxGeometry && m.geometry.parameters.height === 0.085,
        )
        .map((m) => ({
          x: fromThree(m.getWorldPosition(new THREE.Vector3())).x,
          color: `#${(m.material as THREE.MeshStandardMaterial).color.getHexString()}`,
        }))
        .sort((p, q) => p.x - q.x)
        .map((p) => p.color);
    // 'c' has no colour of its own: the default palette's third.
    expect(bodies()).toEqual(['#ff0000', '#00ff00', '#db4437']);
    world.removeRobot('a');
    // 'b' keeps its colour; 'c', now second, takes the palette's second.
    expect(bodies()).toEqual(['#00ff00', '#4285f4']);
    view.dispose();
  });

  it('overlays an occupancy grid, a planned path and a goal, and removes them', () => {
    const world = new World();
    const view = new WorldScene(world, { shadows: false });
    const before = meshes(view.scene).length;
    view.setOccupancyGrid({
      width: 2,
      height: 2,
      resolution: 0.5,
      origin: { x: -0.5, y: -0.5 },
      data: [0, 1, -1, 0.5],
    });
    view.setPlannedPath([
      { x: 0, y: 0 },
      { x: 1, y: 1 },
    ]);
    view.setGoal({ x: 1, y: 1 });
    expect(meshes(view.scene).length).toBeGreaterThan(before);
    view.setOccupancyGrid(undefined);
    view.setGoal(undefined);
    view.setPlannedPath(undefined);
    expect(meshes(view.scene).length).toBe(before);
  });

  it('draws range-sensor rays up to what they hit when asked to', () => {
    const world = new World({ map: { name: 'box', arena: { width: 2, height: 2 } } });
    world.addRobot();
    const view = new WorldScene(world, { shadows: false, showRangeRays: true });
    view.update();
    const rays = view.scene.getObjectsByProperty('type', 'LineSegments')[0] as THREE.LineSegments;
    const position = rays.geometry.getAttribute('position');
    // The first segment is the front ray: from the body edge (0.07 m) to the wall at x = 1 m.
    expect(position.getX(0)).toBeCloseTo(0.07, 5);
    expect(position.getX(1)).toBeCloseTo(1, 5);
  });

  it('hides the robots, their trails and rays when told to, including robots added meanwhile', () => {
    const world = new World();
    world.addRobot();
    const view = new WorldScene(world, { shadows: false, showRangeRays: true });
    const visibleMeshes = () => {
      let n = 0;
      view.scene.traverseVisible((o) => {
        if (o instanceof THREE.Mesh || o instanceof THREE.Line) n += 1;
      });
      return n;
    };
    const withOne = visibleMeshes();
    view.robotsVisible = false;
    const arenaOnly = visibleMeshes();
    expect(arenaOnly).toBeLessThan(withOne);
    world.addRobot();
    view.update();
    expect(visibleMeshes()).toBe(arenaOnly);
    view.robotsVisible = true;
    expect(visibleMeshes()).toBeGreaterThan(withOne);
    view.dispose();
  });

  it('counts a revision for what changes the picture, and none for a frame where nothing did', () => {
    const world = new World();
    const robot = world.addRobot();
    const view = new WorldScene(world, { shadows: false, showRangeRays: true });
    view.update();
    const idle = view.revision;
    view.update();
    view.overlaysVisible = false; // the robot camera's own render: not a change of the scene
    view.overlaysVisible = true;
    expect(view.revision).toBe(idle);
    robot.moveCm(5, 5);
    world.advanceUntil(() => !robot.running, 10_000_000);
    view.update();
    const moved = view.revision;
    expect(moved).toBeGreaterThan(idle);
    view.update();
    expect(view.revision).toBe(moved);
    robot.setLed({ r: 255, g: 0, b: 0, pattern: 'solid' });
    view.update();
    expect(view.revision).toBe(moved + 1);
    view.update();
    expect(view.revision).toBe(moved + 1);
    view.setGoal({ x: 1, y: 0 });
    view.setPlannedPath([
      { x: 0, y: 0 },
      { x: 1, y: 0 },
    ]);
    view.clearTrails();
    view.robotsVisible = false;
    view.robotsVisible = false; // no change
    expect(view.revision).toBe(moved + 5);
    world.setMap('obstacles');
    expect(view.revision).toBeGreaterThan(moved + 5);
    view.dispose();
  });
});
