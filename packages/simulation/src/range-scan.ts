import { normalizeAngle } from '@hal/types';
import type { ScanResult } from '@hal/types';
import type { SimRobot } from './robot/sim-robot.js';
import type { World } from './world.js';

/*
 * `scan` as a robot with a sweeping range sensor could answer it: each ray of the sweep measures
 * a range (true geometry plus the sensor's noise); the robot places each hit where its own
 * believed pose (its odometry, what getPose reports) and the ray's bearing put it, and groups
 * hits that lie together into objects. It knows nothing else: not what an object is, not where
 * the world has it, not what is out of range or behind something nearer.
 */

/** One ray of a sweep that hit something within range. */
export interface RangeHit {
  /** Degrees counter-clockwise from the robot's heading. */
  bearingDeg: number;
  /** Measured range from the body's edge, metres. */
  rangeM: number;
  /** Where the hit is in the believed frame, metres. */
  x: number;
  y: number;
}

/** The bearings, degrees from the heading, of the rays of each scan mode. */
export function sweepBearings(mode: 'full' | 'targeted' | 'quick'): number[] {
  const out: number[] = [];
  if (mode === 'full') for (let a = -180; a < 180; a += 5) out.push(a);
  else if (mode === 'targeted') for (let a = -60; a <= 60; a += 2) out.push(a);
  else out.push(-90, -45, 0, 45, 90);
  return out;
}

/** How far apart two neighbouring hits may be and still belong to one object, metres. */
export function joinDistance(
  rangeFromCentreM: number,
  stepDeg: number,
  noiseSigma: number,
): number {
  // a surface that meets the rays at 24 degrees or more still has its hits joined; a jump in range
  // (the edge of something nearer) splits them
  const step = Math.min(stepDeg, 45) * (Math.PI / 180);
  return 2.5 * rangeFromCentreM * Math.sin(step) + 3 * noiseSigma + 0.02;
}

/** Sweep parameters a scan needs from the range sensor model. */
export interface SweepSensor {
  maxRange: number;
  fieldOfViewDeg: number;
  noiseSigma: number;
  /** Distance from the robot's body edge along a world-frame angle (true geometry), metres. */
  range(angle: number): number;
}

/** The hits of one sweep, in the order of its bearings. */
export function sweepHits(
  world: World,
  robot: SimRobot,
  bearings: readonly number[],
  sensor: SweepSensor,
): (RangeHit | undefined)[] {
  const believed = robot.reportedPose;
  const trueYaw = robot.yaw;
  return bearings.map((bearingDeg) => {
    const a = (bearingDeg * Math.PI) / 180;
    let rangeM = sensor.range(trueYaw + a);
    if (rangeM >= sensor.maxRange) return undefined;
    if (sensor.noiseSigma > 0)
      rangeM = Math.max(0, rangeM + world.random.gaussian(sensor.noiseSigma));
    if (rangeM >= sensor.maxRange) return undefined;
    const fromCentre = rangeM + robot.radius;
    const angle = believed.yaw + a;
    return {
      bearingDeg,
      rangeM,
      x: believed.x + fromCentre * Math.cos(angle),
      y: believed.y + fromCentre * Math.sin(angle),
    };
  });
}

/**
 * Groups neighbouring hits (no miss between them, close enough by {@link joinDistance}) into
 * objects; `circular`: the last ray neighbours the first (a full turn).
 */
export function groupHits(
  hits: readonly (RangeHit | undefined)[],
  stepDeg: number,
  noiseSigma: number,
  radius: number,
  circular: boolean,
): RangeHit[][] {
  const joined = (a: RangeHit | undefined, b: RangeHit | undefined): boolean => {
    if (a === undefined || b === undefined) return false;
    const r = Math.min(a.rangeM, b.rangeM) + radius;
    return Math.hypot(a.x - b.x, a.y - b.y) <= joinDistance(r, stepDeg, noiseSigma);
  };
  const n = hits.length;
  // start where a group begins, so that a circular sweep's group across its ends stays whole
  let start = 0;
  if (circular) {
    const breakAt = hits.findIndex((h, i) => !joined(hits[(i - 1 + n) % n], h));
    if (breakAt < 0) {
      const all = hits.filter((h): h is RangeHit => h !== undefined);
      return all.length === 0 ? [] : [all];
    }
    start = breakAt;
  }
  const groups: RangeHit[][] = [];
  let current: RangeHit[] = [];
  for (let k = 0; k < n; k += 1) {
    const i = (start + k) % n;
    const hit = hits[i];
    const previous = k === 0 ? undefined : hits[(i - 1 + n) % n];
    if (hit === undefined) continue;
    if (current.length > 0 && !joined(previous, hit)) {
      groups.push(current);
      current = [];
    }
    current.push(hit);
  }
  if (current.length > 0) groups.push(current);
  return groups;
}

/** A group of hits as an object the scan reports (without its id). */
function objectOf(
  group: readonly RangeHit[],
  believed: { x: number; y: number; yaw: number },
  spanDeg: number,
  radius: number,
): Omit<ScanResult['objects'][number], 'id'> {
  const x = group.reduce((s, h) => s + h.x, 0) / group.length;
  const y = group.reduce((s, h) => s + h.y, 0) / group.length;
  const first = group[0] as RangeHit;
  const last = group[group.length - 1] as RangeHit;
  const meanRange = group.reduce((s, h) => s + h.rangeM, 0) / group.length + radius;
  const chord = Math.hypot(last.x - first.x, last.y - first.y);
  const bearing = normalizeAngle(Math.atan2(y - believed.y, x - believed.x) - believed.yaw);
  return {
    type: 'obstacle',
    position: { x, y, z: 0 },
    // two rays make it likely, three or more nearly certain
    confidence: 1 - 0.5 ** group.length,
    bearingDeg: (bearing * 180) / Math.PI,
    distanceM: Math.min(...group.map((h) => h.rangeM)),
    // the chord between the outermost hits, widened by one ray's span (half on each side)
    sizeM: chord + meanRange * spanDeg * (Math.PI / 180),
    sensor: 'range',
  };
}

/**
 * A scan from a sweep of the range sensor: objects (grouped hits, each at the mean of its hit
 * points in the believed frame, ids `seen-1`, `seen-2`, ... in order of bearing from the right
 * (-180) round to the left (+180)), the nearest reading, and whether the way ahead is clear by
 * the front reading.
 */
export function rangeScan(
  world: World,
  robot: SimRobot,
  mode: 'full' | 'targeted' | 'quick',
  sensor: SweepSensor,
  frontReadingM: number,
): ScanResult {
  const bearings = sweepBearings(mode);
  const stepDeg = bearings.length > 1 ? (bearings[1] as number) - (bearings[0] as number) : 360;
  const hits = sweepHits(world, robot, bearings, sensor);
  const believed = robot.reportedPose;
  const groups = groupHits(hits, stepDeg, sensor.noiseSigma, robot.radius, mode === 'full');
  const spanDeg = Math.min(stepDeg, sensor.fieldOfViewDeg);
  const objects = groups
    .map((g) => objectOf(g, believed, spanDeg, robot.radius))
    .sort((a, b) => (a.bearingDeg ?? 0) - (b.bearingDeg ?? 0))
    .map((o, i) => ({ id: `seen-${i + 1}`, ...o }));
  const ranges = hits.flatMap((h) => (h === undefined ? [] : [h.rangeM]));
  const result: ScanResult = {
    objects,
    clearAhead: frontReadingM > CLEARANCE_M,
    frame: 'odometry',
    source: 'simulation',
  };
  if (ranges.length > 0) result.nearestObstacle = Math.min(...ranges);
  return result;
}

/** The way ahead is clear when the front range sensor reads more than this, metres. */
export const CLEARANCE_M = 0.3;
