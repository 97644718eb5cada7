import { cameraProjection, pixelRay } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import { cameraModel } from '@hal/types';
import type { CameraModel } from '@hal/types';
import type { SimRobot } from './robot/sim-robot.js';
import { hitsXFace, rayEnter } from './shapes.js';
import type { CylinderSolid, Rgb, Solid } from './shapes.js';
import type { World } from './world.js';

/*
 * A software camera needing no GPU and no browser: a ray caster over the world's plan (boxes and
 * cylinders with heights) that casts one ray per pixel through the robot's camera model (the
 * pinhole of @hal/kinematics, the very projection perception inverts), with a checkered floor, a
 * sky gradient, face shading and distance fog. It draws what the robot's camera sees, so a
 * headless agent gets real frames.
 */

/** An RGBA image, row-major, 4 bytes per pixel. */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array;
}

/**
 * The camera model the renderer draws with (any field left out is the V1 camera's, see
 * `V1_CAMERA` of @hal/types), and how far it draws.
 */
export interface CameraOptions extends Partial<CameraModel> {
  /** Farthest thing drawn, metres. Default 15. */
  maxDistanceM?: number;
}

const SKY_TOP: Rgb = { r: 96, g: 148, b: 214 };
const SKY_HORIZON: Rgb = { r: 205, g: 222, b: 240 };
const FOG: Rgb = { r: 200, g: 210, b: 222 };
const FLOOR_A: Rgb = { r: 214, g: 208, b: 196 };
const FLOOR_B: Rgb = { r: 184, g: 178, b: 166 };
/** Other robots: a dark grey body, a colour no object of a task has. */
const ROBOT_COLOR: Rgb = { r: 70, g: 72, b: 78 };

/** The camera model of `options`: V1's where a field is left out; throws when one is invalid. */
export function cameraModelOf(options: CameraOptions = {}): CameraModel {
  const { maxDistanceM: _max, ...model } = options;
  return cameraModel(model);
}

/** The camera's pose in the world: lens position (metres), heading and tilt (radians, down +). */
export function cameraPose(
  robot: SimRobot,
  options: CameraOptions = {},
): { x: number; y: number; z: number; yaw: number; tilt: number } {
  const camera = cameraModelOf(options);
  const c = Math.cos(robot.yaw);
  const s = Math.sin(robot.yaw);
  return {
    x: robot.x + camera.forwardM * c - camera.leftM * s,
    y: robot.y + camera.forwardM * s + camera.leftM * c,
    z: camera.heightM,
    yaw: robot.yaw,
    tilt: (camera.tiltDeg * Math.PI) / 180,
  };
}

/** Per pixel of a camera model: the unit horizontal direction (robot frame) and the slope. */
interface RayTable {
  key: string;
  projection: CameraProjection;
  hx: Float64Array;
  hy: Float64Array;
  slope: Float64Array;
  /** Per column, the least and greatest bearing (radians, left +) of its pixels' rays. */
  columnMin: Float64Array;
  columnMax: Float64Array;
  /** The slope of the top row's middle ray: the sky's gradient spans up to it. */
  topSlope: number;
}

let cachedRays: RayTable | undefined;

function raysOf(camera: CameraModel): RayTable {
  const key = JSON.stringify(camera);
  if (cachedRays?.key === key) return cachedRays;
  const projection = cameraProjection(camera);
  const n = camera.width * camera.height;
  const hx = new Float64Array(n);
  const hy = new Float64Array(n);
  const slope = new Float64Array(n);
  const columnMin = new Float64Array(camera.width).fill(Number.POSITIVE_INFINITY);
  const columnMax = new Float64Array(camera.width).fill(Number.NEGATIVE_INFINITY);
  for (let row = 0; row < camera.height; row += 1) {
    for (let col = 0; col < camera.width; col += 1) {
      const ray = pixelRay(projection, col + 0.5, row + 0.5);
      const horizontal = Math.hypot(ray.x, ray.y);
      const i = row * camera.width + col;
      hx[i] = ray.x / horizontal;
      hy[i] = ray.y / horizontal;
      slope[i] = ray.z / horizontal;
      const bearing = Math.atan2(ray.y, ray.x);
      columnMin[col] = Math.min(columnMin[col] ?? 0, bearing);
      columnMax[col] = Math.max(columnMax[col] ?? 0, bearing);
    }
  }
  const topSlope = Math.max(0.02, slope[Math.floor(camera.width / 2)] ?? 0);
  cachedRays = { key, projection, hx, hy, slope, columnMin, columnMax, topSlope };
  return cachedRays;
}

function insideFootprint(x: number, y: number, solid: Solid): boolean {
  if (solid.kind === 'box') {
    return x >= solid.minX && x <= solid.maxX && y >= solid.minY && y <= solid.maxY;
  }
  const dx = x - solid.x;
  const dy = y - solid.y;
  return dx * dx + dy * dy <= solid.radius * solid.radius;
}

/** Renders what `robot`'s camera sees in `world`. */
export function renderRobotView(
  world: World,
  robot: SimRobot,
  options: CameraOptions = {},
): RgbaImage {
  const camera = cameraModelOf(options);
  const { width, height } = camera;
  const maxDist = options.maxDistanceM ?? 15;
  const cam = cameraPose(robot, options);
  const rays = raysOf(camera);
  const f = rays.projection.f;
  const data = new Uint8Array(width * height * 4);
  const cosYaw = Math.cos(cam.yaw);
  const sinYaw = Math.sin(cam.yaw);

  // The solids this camera could see: in front of the lens (with their size as margin), each
  // with the bearings (relative to the heading) it spans, so a column casts only at its own.
  const solids: Solid[] = [];
  const spans: Array<{ centre: number; half: number }> = [];
  const consider = (solid: Solid): void => {
    const [sx, sy, reach] =
      solid.kind === 'box'
        ? [
            (solid.minX + solid.maxX) / 2,
            (solid.minY + solid.maxY) / 2,
            Math.hypot(solid.maxX - solid.minX, solid.maxY - solid.minY) / 2,
          ]
        : [solid.x, solid.y, solid.radius];
    const ahead = (sx - cam.x) * cosYaw + (sy - cam.y) * sinYaw;
    const side = -(sx - cam.x) * sinYaw + (sy - cam.y) * cosYaw;
    const distance = Math.hypot(sx - cam.x, sy - cam.y);
    if (ahead <= -reach || distance - reach >= maxDist) return;
    solids.push(solid);
    spans.push({
      centre: Math.atan2(side, ahead),
      half: distance <= reach ? Math.PI : Math.asin(reach / distance) + 1e-6,
    });
  };
  for (const solid of world.solids) consider(solid);
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
    consider(body);
  }

  // Per column, the solids whose bearings overlap the column's.
  const columnSolids: Solid[][] = [];
  for (let col = 0; col < width; col += 1) {
    const lo = rays.columnMin[col] ?? 0;
    const hi = rays.columnMax[col] ?? 0;
    const list: Solid[] = [];
    solids.forEach((solid, k) => {
      const span = spans[k];
      if (span === undefined) return;
      if (span.half >= Math.PI || (span.centre + span.half >= lo && span.centre - span.half <= hi))
        list.push(solid);
    });
    columnSolids.push(list);
  }

  for (let row = 0; row < height; row += 1) {
    for (let col = 0; col < width; col += 1) {
      const i = row * width + col;
      const candidates = columnSolids[col] ?? solids;
      const rx = rays.hx[i] ?? 0;
      const ry = rays.hy[i] ?? 0;
      const slope = rays.slope[i] ?? 0;
      const dx = rx * cosYaw - ry * sinYaw;
      const dy = rx * sinYaw + ry * cosYaw;
      // Horizontal distance to the floor (Infinity at and above the horizon).
      // Horizontal distance to the floor, or the drawing distance (nothing is drawn beyond it).
      const floor = slope < 0 ? cam.z / -slope : Number.POSITIVE_INFINITY;
      let best = Math.min(floor, maxDist);
      let hit: Solid | undefined;
      let onTop = false;
      for (const solid of candidates) {
        const t = rayEnter(cam.x, cam.y, dx, dy, solid);
        if (!(t < best)) continue;
        const z = cam.z + slope * t;
        if (z >= 0 && z <= solid.height) {
          best = t;
          hit = solid;
          onTop = false;
        } else if (z > solid.height && slope < 0) {
          // Over the near edge and down onto the top face.
          const tTop = (solid.height - cam.z) / slope;
          if (tTop < best && insideFootprint(cam.x + dx * tTop, cam.y + dy * tTop, solid)) {
            best = tTop;
            hit = solid;
            onTop = true;
          }
        }
      }
      let r: number;
      let g: number;
      let b: number;
      let fog: number;
      if (hit !== undefined) {
        let shade: number;
        if (onTop) {
          shade = 0.9;
        } else if (hit.kind === 'box') {
          shade = hitsXFace(cam.x, dx, best, hit) ? 0.78 : 1;
        } else {
          const nx = cam.x + dx * best - hit.x;
          const ny = cam.y + dy * best - hit.y;
          const facing = -(nx * dx + ny * dy) / Math.hypot(nx, ny);
          shade = 0.55 + 0.45 * Math.max(0, facing);
        }
        // A darker band along a side's top edge (two pixels) makes each outline readable.
        const z = cam.z + slope * best;
        if (!onTop && hit.height - z < (2 * best) / f) shade *= 0.7;
        r = hit.color.r * shade;
        g = hit.color.g * shade;
        b = hit.color.b * shade;
        fog = Math.min(1, best / maxDist);
      } else if (floor <= maxDist) {
        const fx = cam.x + dx * best;
        const fy = cam.y + dy * best;
        const tile = (Math.floor(fx / 0.5) + Math.floor(fy / 0.5)) & 1;
        const c = tile === 0 ? FLOOR_A : FLOOR_B;
        r = c.r;
        g = c.g;
        b = c.b;
        fog = Math.min(1, best / maxDist);
      } else {
        // The sky, or the floor beyond the drawing distance (fog).
        if (slope < 0) {
          r = FOG.r;
          g = FOG.g;
          b = FOG.b;
        } else {
          const k = Math.min(1, slope / rays.topSlope);
          r = SKY_HORIZON.r + (SKY_TOP.r - SKY_HORIZON.r) * k;
          g = SKY_HORIZON.g + (SKY_TOP.g - SKY_HORIZON.g) * k;
          b = SKY_HORIZON.b + (SKY_TOP.b - SKY_HORIZON.b) * k;
        }
        fog = 0;
      }
      const o = i * 4;
      data[o] = r + (FOG.r - r) * fog;
      data[o + 1] = g + (FOG.g - g) * fog;
      data[o + 2] = b + (FOG.b - b) * fog;
      data[o + 3] = 255;
    }
  }
  return { width, height, data };
}
