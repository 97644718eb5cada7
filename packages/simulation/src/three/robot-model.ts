import * as THREE from 'three';
import type { CameraOptions } from '../camera.js';
import { cameraModelOf, cameraPose } from '../camera.js';
import type { SimRobot } from '../robot/sim-robot.js';
import { toThree } from './coordinates.js';

/** A robot's 3D model: body, wheels, camera lens, heading arrow and status LED. */
export class RobotModel {
  readonly group = new THREE.Group();
  readonly #led: THREE.MeshStandardMaterial;

  constructor(robot: SimRobot, color: string, shadows: boolean) {
    const group = this.group;
    const side = robot.radius * Math.SQRT2 * 0.95;
    const body = new THREE.Mesh(
      new THREE.BoxGeometry(side, 0.085, side),
      new THREE.MeshStandardMaterial({ color, roughness: 0.45, metalness: 0.1 }),
    );
    body.position.y = 0.05;
    body.castShadow = shadows;
    group.add(body);
    const wheelMaterial = new THREE.MeshStandardMaterial({ color: '#263238', roughness: 0.9 });
    for (const sideSign of [1, -1]) {
      const wheel = new THREE.Mesh(
        new THREE.CylinderGeometry(0.03, 0.03, 0.012, 24),
        wheelMaterial,
      );
      wheel.rotation.x = Math.PI / 2;
      wheel.position.set(0, 0.03, sideSign * (side / 2 + 0.007));
      wheel.castShadow = shadows;
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
    this.#led = new THREE.MeshStandardMaterial({ color: '#222222', emissive: '#111111' });
    const ledMesh = new THREE.Mesh(new THREE.SphereGeometry(0.01, 16, 8), this.#led);
    ledMesh.position.set(-side / 4, 0.097, 0);
    group.add(ledMesh);
  }

  /** Puts the model at the robot's pose and lights its LED as the robot's is lit. */
  follow(robot: SimRobot): void {
    this.group.position.copy(toThree(robot.x, robot.y));
    this.group.rotation.y = robot.yaw;
    const led = robot.led;
    const on = led.pattern !== 'off' && (led.r > 0 || led.g > 0 || led.b > 0);
    this.#led.emissive.setRGB(
      on ? led.r / 255 : 0.05,
      on ? led.g / 255 : 0.05,
      on ? led.b / 255 : 0.05,
    );
  }
}

/**
 * A camera at `robot`'s camera pose, looking where it looks (for the robot's view). Reuses and
 * updates `into` when given.
 */
export function placeRobotCamera(
  robot: SimRobot,
  options: CameraOptions = {},
  into?: THREE.PerspectiveCamera,
): THREE.PerspectiveCamera {
  const model = cameraModelOf(options);
  const hfov = (model.fieldOfViewDeg * Math.PI) / 180;
  const vfov = 2 * Math.atan(Math.tan(hfov / 2) * (model.height / model.width));
  const camera = into ?? new THREE.PerspectiveCamera(1, 1, 0.01, 40);
  camera.fov = (vfov * 180) / Math.PI;
  camera.aspect = model.width / model.height;
  camera.updateProjectionMatrix();
  const pose = cameraPose(robot, options);
  camera.position.copy(toThree(pose.x, pose.y, pose.z));
  // Looking along the heading, tilted down by the model's tilt.
  const level = Math.cos(pose.tilt);
  camera.lookAt(
    toThree(
      pose.x + level * Math.cos(pose.yaw),
      pose.y + level * Math.sin(pose.yaw),
      pose.z - Math.sin(pose.tilt),
    ),
  );
  return camera;
}
