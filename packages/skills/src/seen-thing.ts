import type { Pose2D } from '@hal/navigation';
import type { RememberedObject } from '@hal/perception';
import { angleDifference, normalizeAngle } from '@hal/types';
import { deg0, m2 } from './skill-result.js';

/**
 * An object as a skill reports it: its memory id, what it looks like, and where it is from the
 * robot now (distance between centres, bearing left positive) and in the odometry frame.
 */
export interface SeenThing {
  /** The memory's name for it, e.g. "red box 1": no world knowledge in it. */
  id: string;
  colour: string;
  kind: 'box' | 'pillar' | 'unknown';
  /** From the robot's centre to the object's estimated centre, metres. */
  distanceM: number;
  /** Off the robot's heading, degrees, left positive, in (-180, 180]. */
  bearingDeg: number;
  /** Its estimated centre, odometry frame, metres. */
  x: number;
  y: number;
}

const round2 = (v: number) => Math.round(v * 100) / 100;

const DEG = Math.PI / 180;

/** Degrees in (-180, 180] (`normalizeAngle` of @hal/types, in degrees). */
export function wrapDeg(deg: number): number {
  return normalizeAngle(deg * DEG) / DEG;
}

/** A remembered object as seen from `pose`. */
export function seenFrom(object: RememberedObject, pose: Pose2D): SeenThing {
  const dx = object.x - pose.x;
  const dy = object.y - pose.y;
  const bearing = angleDifference(Math.atan2(dy, dx), pose.yaw) / DEG;
  return {
    id: object.id,
    colour: object.colour,
    kind: object.kind,
    distanceM: round2(Math.hypot(dx, dy)),
    bearingDeg: Math.round(bearing),
    x: round2(object.x),
    y: round2(object.y),
  };
}

/** "the red box 1 1.20 m away, 15° left" */
export function describeThing(thing: SeenThing): string {
  const side =
    Math.abs(thing.bearingDeg) < 3
      ? 'straight ahead'
      : `${deg0(Math.abs(thing.bearingDeg))}° ${thing.bearingDeg > 0 ? 'left' : 'right'}`;
  return `the ${thing.id} ${m2(thing.distanceM)} m away, ${side}`;
}

/** A list of things in words, nearest first: "the red box 1 ...; the blue pillar 1 ...". */
export function describeThings(things: readonly SeenThing[]): string {
  return things.map(describeThing).join('; ');
}
