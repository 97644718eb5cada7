import type { DistanceSensors, ScanResult } from '@hal/types';
import type { SimRobot } from './robot/sim-robot.js';
import { rangeScan } from './range-scan.js';
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
 * A sweep of the range sensor around the robot: `full` 360 degrees every 5, `targeted` +/-60
 * degrees every 2, `quick` the bearings of the five range sensors. Reports what the rays hit
 * within range, grouped into objects placed in the robot's believed frame (see range-scan.ts):
 * never where the world has them, nor anything out of range or hidden behind something nearer.
 */
export function scanAround(
  world: World,
  robot: SimRobot,
  mode: 'full' | 'targeted' | 'quick',
  options: RangeSensorOptions = {},
): ScanResult {
  const o = withDefaults(options);
  return rangeScan(
    world,
    robot,
    mode,
    {
      maxRange: o.maxRange,
      fieldOfViewDeg: o.fieldOfViewDeg,
      noiseSigma: o.noiseSigma,
      range: (angle) => rangeAlong(world, robot, angle, o.maxRange).distance,
    },
    coneReading(world, robot, 0, o),
  );
}
