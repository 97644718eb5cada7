import type { ColourName } from './palette.js';

/** What an object looks like it is. */
export type ObjectKind = 'box' | 'pillar' | 'unknown';

/** A pixel rectangle in the image: columns left..right and rows top..bottom, inclusive. */
export interface ImageBox {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** One object seen in one frame. Robot frame REP-103 (x forward, y left), metres, radians. */
export interface SeenObject {
  /** Its colour. */
  colour: ColourName;
  /** What it looks like: a box (flat faces), a pillar (round), or unknown. */
  kind: ObjectKind;
  /** Words for it, e.g. "red box". */
  label: string;
  /** Bearing of its centre from the robot's heading, degrees, left positive. */
  bearingDeg: number;
  /** Ground distance from the robot's centre to the object's centre, metres (estimated). */
  distanceM: number;
  /** Ground distance from the robot's centre to the nearest point of its base, metres. */
  nearDistanceM: number;
  /** Its width across the line of sight, metres. */
  widthM: number;
  /** Its height, metres; a lower bound when `partial` says its top is cut off. */
  heightM: number;
  /** How sure the detector is, 0..1. */
  confidence: number;
  /** Its centre in the robot's frame at capture, metres. */
  robot: { x: number; y: number };
  /** Its centre in the world (odometry) frame, from the pose at capture, metres. */
  world: { x: number; y: number };
  /** Where it is in the image. */
  image: ImageBox;
  /**
   * What of it is out of view: `base` (its foot is below the image: nearer than the nearest
   * visible floor, distances are upper bounds), `side` (cut by the left or right edge), `top`.
   */
  partial: Array<'base' | 'side' | 'top'>;
  /** Which detector saw it. */
  detector: string;
}
