import type { DistanceSensors, IMUReading, ScanResult } from '@hal/types';
import type { SimRobot } from './robot/sim-robot.js';
import { rayEnter } from './shapes.js';
import type { Solid } from './shapes.js';
import type { World } from './world.js';

/** The simulated range sensors: where they look, how far and how wide, and their noise. */
export interface RangeSensorOptions {
  /** Maximum range, metres; the reading when nothing is in range. Default 2. */
  maxRange?: number;
  /** Full field of view of each sensor, degrees; the reading is the nearest hit in it. Default 25. */
  fieldOfViewDeg?: number;
  /** Rays per sensor across its field of view. Default 5. */
  rays?: number;
  /** Standard deviation of Gaussian noise added to in-range readings, metres. Default 0. */
  noiseSigma?: number;
}

const DEG = Math.PI / 180;
const G = 9.80665;

/**
 * Distance from the robot's body edge to the nearest solid (or other robot) seen by a ray from
 * its centre at `angle` (world frame), capped at `maxRange`.
 */
export function rangeAlong(
  world: World,
  robot: SimRobot,
  angle: number,
  maxRange: number,
): { distance: number; solid: Solid | undefined; robotId: string | undefined } {
  const dx = Math.cos(angle);
  const dy = Math.sin(angle);
  const limit = maxRange + robot.radius;
  let best = limit;
  let solid: Solid | undefined;
  let robotId: string | undefined;
  for (const s of world.solids) {
    const t = rayEnter(robot.x, robot.y, dx, dy, s);
    if (t < best) {
      best = t;
      solid = s;
    }
  }
  for (const other of world.robots) {
    if (other === robot) continue;
    const t = rayEnter(robot.x, robot.y, dx, dy, {
      kind: 'cylinder',
      x: other.x,
      y: other.y,
      radius: other.radius,
      height: 0.1,
      color: { r: 0, g: 0, b: 0 },
      role: 'robot',
      index: 0,
    });
    if (t < best) {
      best = t;
      solid = undefined;
      robotId = other.id;
    }
  }
  if (best >= limit) return { distance: maxRange, solid: undefined, robotId: undefined };
  return { distance: Math.max(0, Math.min(maxRange, best - robot.radius)), solid, robotId };
}

/** One cone-shaped sensor: the nearest reading across its rays, plus seeded noise. */
function coneReading(
  world: World,
  robot: SimRobot,
  offset: number,
  options: Required<RangeSensorOptions>,
): number {
  const { maxRange, fieldOfViewDeg, rays, noiseSigma } = options;
  let nearest = maxRange;
  for (let i = 0; i < rays; i += 1) {
    const spread = rays === 1 ? 0 : (i / (rays - 1) - 0.5) * fieldOfViewDeg * DEG;
    nearest = Math.min(
      nearest,
      rangeAlong(world, robot, robot.yaw + offset + spread, maxRange).distance,
    );
  }
  if (noiseSigma > 0 && nearest < maxRange) {
    nearest = Math.min(maxRange, Math.max(0, nearest + world.random.gaussian(noiseSigma)));
  }
  return nearest;
}

function withDefaults(options: RangeSensorOptions): Required<RangeSensorOptions> {
  return {
    maxRange: options.maxRange ?? 2,
    fieldOfViewDeg: options.fieldOfViewDeg ?? 25,
    rays: options.rays ?? 5,
    noiseSigma: options.noiseSigma ?? 0,
  };
}

/** Range readings front, left (+90 degrees), right, and the two diagonals, metres. */
export function readDistanceSensors(
  world: World,
  robot: SimRobot,
  options: RangeSensorOptions = {},
): DistanceSensors {
  const o = withDefaults(options);
  return {
    front: coneReading(world, robot, 0, o),
    left: coneReading(world, robot, Math.PI / 2, o),
    right: coneReading(world, robot, -Math.PI / 2, o),
    frontLeft: coneReading(world, robot, Math.PI / 4, o),
    frontRight: coneReading(world, robot, -Math.PI / 4, o),
    limits: { minM: 0, maxM: o.maxRange, fieldOfViewDeg: o.fieldOfViewDeg },
    source: 'simulation',
  };
}

/**
 * A sweep of rays around the robot: `full` 360 degrees every 5, `targeted` +/-60 degrees every
 * 2, `quick` the five range sensors. Each solid seen is reported once, at its centre.
 */
export function scanAround(
  world: World,
  robot: SimRobot,
  mode: 'full' | 'targeted' | 'quick',
  options: RangeSensorOptions = {},
): ScanResult {
  const o = withDefaults(options);
  const angles: number[] = [];
  if (mode === 'full') for (let a = -180; a < 180; a += 5) angles.push(a);
  else if (mode === 'targeted') for (let a = -60; a <= 60; a += 2) angles.push(a);
  else angles.push(-90, -45, 0, 45, 90);
  const seen = new Map<string, ScanResult['objects'][number]>();
  let nearest = Number.POSITIVE_INFINITY;
  for (const a of angles) {
    const hit = rangeAlong(world, robot, robot.yaw + a * DEG, o.maxRange);
    if (hit.distance >= o.maxRange) continue;
    nearest = Math.min(nearest, hit.distance);
    if (hit.robotId !== undefined) {
      const other = world.robot(hit.robotId);
      seen.set(`robot:${hit.robotId}`, {
        id: hit.robotId,
        type: 'robot',
        position: { x: other.x, y: other.y, z: 0 },
        confidence: 1,
      });
    } else if (hit.solid !== undefined) {
      const s = hit.solid;
      const id = `${s.role}-${s.index}`;
      const position =
        s.kind === 'box'
          ? { x: (s.minX + s.maxX) / 2, y: (s.minY + s.maxY) / 2, z: s.height / 2 }
          : { x: s.x, y: s.y, z: s.height / 2 };
      seen.set(id, {
        id,
        type: s.role === 'obstacle' ? s.kind : s.role,
        position,
        confidence: 1,
      });
    }
  }
  const front = coneReading(world, robot, 0, { ...o, noiseSigma: 0 });
  const result: ScanResult = {
    objects: [...seen.values()],
    clearAhead: front > 0.3,
    source: 'simulation',
  };
  if (Number.isFinite(nearest)) result.nearestObstacle = nearest;
  return result;
}

/**
 * What an IMU on the robot would read: acceleration from the motion profile (robot frame,
 * gravity +z), rotation rate about z, and the heading.
 */
export function readImu(robot: SimRobot): IMUReading {
  const now = robot.nowUs;
  const v = robot.velocity(now);
  const before = robot.velocity(Math.max(0, now - 1000));
  const ax = robot.running ? (v.linear - before.linear) / 0.001 : 0;
  return {
    acceleration: { x: ax, y: v.linear * v.angular, z: G },
    gyroscope: { x: 0, y: 0, z: v.angular },
    heading: robot.yaw,
    source: 'simulation',
  };
}
