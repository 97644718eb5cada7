import type { SimRobot } from './robot/sim-robot.js';
import { hitsXFace, rayEnter } from './shapes.js';
import type { CylinderSolid, Rgb, Solid } from './shapes.js';
import type { World } from './world.js';

/*
 * A software camera needing no GPU and no browser: a column ray caster over the world's plan
 * (boxes and cylinders with heights), with a checkered floor, a sky gradient, face shading and
 * distance fog. It draws what the robot's camera sees, so a headless agent gets real frames.
 */

/** An RGBA image, row-major, 4 bytes per pixel. */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}

/** Where the camera sits on the robot and what it sees. */
export interface CameraOptions {
  /** Image width, pixels. Default 320 (the ESP32-CAM's QVGA). */
  width?: number;
  /** Image height, pixels. Default 240. */
  height?: number;
  /** Horizontal field of view, degrees. Default 62 (the OV2640's standard lens). */
  fieldOfViewDeg?: number;
  /** Lens height above the floor, metres. Default 0.09. */
  heightM?: number;
  /** Lens distance ahead of the robot's centre, metres. Default 0.05. */
  forwardM?: number;
  /** Farthest thing drawn, metres. Default 15. */
  maxDistanceM?: number;
}

const SKY_TOP: Rgb = { r: 96, g: 148, b: 214 };
const SKY_HORIZON: Rgb = { r: 205, g: 222, b: 240 };
const FOG: Rgb = { r: 200, g: 210, b: 222 };
const FLOOR_A: Rgb = { r: 214, g: 208, b: 196 };
const FLOOR_B: Rgb = { r: 184, g: 178, b: 166 };
const ROBOT_COLOR: Rgb = { r: 250, g: 180, b: 40 };

interface Hit {
  t: number;
  solid: Solid;
}

/** The camera's pose in the world: position (metres) and heading (radians). */
export function cameraPose(
  robot: SimRobot,
  options: CameraOptions = {},
): { x: number; y: number; z: number; yaw: number } {
  const forward = options.forwardM ?? 0.05;
  return {
    x: robot.x + forward * Math.cos(robot.yaw),
    y: robot.y + forward * Math.sin(robot.yaw),
    z: options.heightM ?? 0.09,
    yaw: robot.yaw,
  };
}

/** Renders what `robot`'s camera sees in `world`. */
export function renderRobotView(
  world: World,
  robot: SimRobot,
  options: CameraOptions = {},
): RgbaImage {
  const width = options.width ?? 320;
  const height = options.height ?? 240;
  const fov = ((options.fieldOfViewDeg ?? 62) * Math.PI) / 180;
  const maxDist = options.maxDistanceM ?? 15;
  const cam = cameraPose(robot, options);
  const data = new Uint8Array(width * height * 4);
  const f = width / 2 / Math.tan(fov / 2);
  const horizon = height / 2;

  const solids: Solid[] = [...world.solids];
  for (const other of world.robots) {
    if (other === robot) continue;
    const body: CylinderSolid = {
      kind: 'cylinder',
      x: other.x,
      y: other.y,
      radius: other.radius,
      height: 0.1,
      color: ROBOT_COLOR,
      role: 'robot',
      index: 0,
    };
    solids.push(body);
  }

  const put = (row: number, col: number, c: Rgb, fog: number): void => {
    const i = (row * width + col) * 4;
    data[i] = c.r + (FOG.r - c.r) * fog;
    data[i + 1] = c.g + (FOG.g - c.g) * fog;
    data[i + 2] = c.b + (FOG.b - c.b) * fog;
    data[i + 3] = 255;
  };

  const hits: Hit[] = [];
  for (let col = 0; col < width; col += 1) {
    const offset = -Math.atan((col + 0.5 - width / 2) / f);
    const angle = cam.yaw + offset;
    const dx = Math.cos(angle);
    const dy = Math.sin(angle);
    const cosOff = Math.cos(offset);

    // Sky and floor.
    for (let row = 0; row < height; row += 1) {
      const v = row + 0.5 - horizon;
      if (v <= 0) {
        const k = Math.min(1, -v / horizon);
        put(
          row,
          col,
          {
            r: SKY_HORIZON.r + (SKY_TOP.r - SKY_HORIZON.r) * k,
            g: SKY_HORIZON.g + (SKY_TOP.g - SKY_HORIZON.g) * k,
            b: SKY_HORIZON.b + (SKY_TOP.b - SKY_HORIZON.b) * k,
          },
          0,
        );
      } else {
        const along = (f * cam.z) / v / cosOff;
        const fx = cam.x + dx * along;
        const fy = cam.y + dy * along;
        const tile = (Math.floor(fx / 0.5) + Math.floor(fy / 0.5)) & 1;
        put(row, col, tile === 0 ? FLOOR_A : FLOOR_B, Math.min(1, along / maxDist));
      }
    }

    // Solids, far to near, so nearer ones cover farther ones where they overlap.
    hits.length = 0;
    for (const solid of solids) {
      const t = rayEnter(cam.x, cam.y, dx, dy, solid);
      if (t > 1e-6 && t < maxDist) hits.push({ t, solid });
    }
    hits.sort((a, b) => b.t - a.t);
    for (const { t, solid } of hits) {
      const perp = t * cosOff;
      const top = Math.max(0, Math.floor(horizon + (f * (cam.z - solid.height)) / perp));
      const bottom = Math.min(height - 1, Math.floor(horizon + (f * cam.z) / perp));
      let shade: number;
      if (solid.kind === 'box') {
        shade = hitsXFace(cam.x, dx, t, solid) ? 0.78 : 1;
      } else {
        const nx = cam.x + dx * t - solid.x;
        const ny = cam.y + dy * t - solid.y;
        const facing = -(nx * dx + ny * dy) / Math.hypot(nx, ny);
        shade = 0.55 + 0.45 * Math.max(0, facing);
      }
      const fog = Math.min(1, t / maxDist);
      const c = solid.color;
      for (let row = top; row <= bottom; row += 1) {
        // A darker band along the top edge makes each object's outline readable.
        const edge = row - top < 2 ? 0.7 : 1;
        put(row, col, { r: c.r * shade * edge, g: c.g * shade * edge, b: c.b * shade * edge }, fog);
      }
    }
  }
  return { width, height, data };
}
