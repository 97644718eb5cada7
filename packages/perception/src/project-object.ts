import { floorPointOfPixel, pixelRay } from '@hal/kinematics';
import type { CameraProjection, FloorPoint } from '@hal/kinematics';
import type { Pose2D } from '@hal/navigation';
import type { ColourName } from './palette.js';
import type { ImageBox, ObjectKind, SeenObject } from './seen-object.js';

/**
 * What a detector says of one object: its colour and kind, its box in the image, and, where the
 * detector knows it, per column the row just below the object's visible base (the first floor
 * pixel): a colour segmentation knows each column's base, a vision model only its box.
 */
export interface Detection {
  colour: ColourName;
  kind: ObjectKind;
  box: ImageBox;
  confidence: number;
  /** Per column from `box.left`, the row of the base's lower edge, or -1 where it is hidden. */
  baseRows?: Int16Array;
  /** The detector's name, e.g. "colour" or "vlm:gpt-4o-mini". */
  detector: string;
}

/** Projects a robot-frame point into the world frame of `pose`. */
export function toWorld(pose: Pose2D, point: FloorPoint): FloorPoint {
  const c = Math.cos(pose.yaw);
  const s = Math.sin(pose.yaw);
  return { x: pose.x + point.x * c - point.y * s, y: pose.y + point.x * s + point.y * c };
}

/** The base row of the first visible column from one end (within `reach` columns), or -1. */
function endRow(rows: Int16Array, fromLeft: boolean, reach: number): number {
  for (let k = 0; k < Math.min(reach, rows.length); k += 1) {
    const row = rows[fromLeft ? k : rows.length - 1 - k] ?? -1;
    if (row >= 0) return row;
  }
  return -1;
}

/**
 * A detection placed on the floor through the camera model. Its base points: the nearest (the
 * lowest visible base row) and its two ends (the outer edges of its end columns, at their own
 * base rows). Its centre: for a pillar, on the bisector of its two sides at
 * near / (1 - sin(half its angular width)); for anything else, taken as a box with a square
 * footprint, the middle of its longer visible face, half that face's length farther.
 * Undefined when its base is above the horizon (nothing on the floor to stand on).
 */
export function projectDetection(
  detection: Detection,
  projection: CameraProjection,
  pose: Pose2D,
): SeenObject | undefined {
  const { box } = detection;
  const { width, height } = projection.camera;
  const lens = { x: projection.camera.forwardM, y: projection.camera.leftM };
  // The nearest base point; columns tied at the lowest row (a face seen square-on) stand for
  // their middle.
  let nearRow = -1;
  let nearCol = (box.left + box.right + 1) / 2;
  const rows = detection.baseRows;
  if (rows !== undefined) {
    for (const row of rows) nearRow = Math.max(nearRow, row);
    let sum = 0;
    let n = 0;
    rows.forEach((row, c) => {
      if (row === nearRow) {
        sum += box.left + c + 0.5;
        n += 1;
      }
    });
    if (n > 0) nearCol = sum / n;
  }
  if (nearRow < 0) nearRow = box.bottom + 1;
  const near = floorPointOfPixel(projection, nearCol, nearRow);
  if (near === undefined) return undefined;
  const leftRow = rows === undefined ? nearRow : endRow(rows, true, 4);
  const rightRow = rows === undefined ? nearRow : endRow(rows, false, 4);
  const left = floorPointOfPixel(projection, box.left, leftRow < 0 ? nearRow : leftRow) ?? near;
  const right =
    floorPointOfPixel(projection, box.right + 1, rightRow < 0 ? nearRow : rightRow) ?? near;
  const span = Math.hypot(left.x - right.x, left.y - right.y);
  // The bearings (from the lens) of its two sides.
  const leftBearing = Math.atan2(left.y - lens.y, left.x - lens.x);
  const rightBearing = Math.atan2(right.y - lens.y, right.x - lens.x);
  const halfAngle = Math.abs(leftBearing - rightBearing) / 2;
  const midBearing = (leftBearing + rightBearing) / 2;
  const nearDepth = Math.hypot(near.x - lens.x, near.y - lens.y);
  let centre: FloorPoint;
  let widthM: number;
  if (detection.kind === 'pillar') {
    const depth = nearDepth / Math.max(0.05, 1 - Math.sin(halfAngle));
    centre = { x: lens.x + depth * Math.cos(midBearing), y: lens.y + depth * Math.sin(midBearing) };
    widthM = 2 * (depth - nearDepth);
  } else if (detection.kind === 'box' || span > 0) {
    // A box's centre is the middle of any whole face it shows, half that face's length farther
    // (a square footprint). Its ends and its nearest point give its faces: one (the near point on
    // the line between the ends, seen square-on) or two (a corner between them); the longer is
    // measured best.
    const lineX = right.x - left.x;
    const lineY = right.y - left.y;
    const offLine =
      Math.abs((near.x - left.x) * lineY - (near.y - left.y) * lineX) / Math.max(1e-9, span);
    let a = left;
    let b = right;
    if (offLine > 0.08 * span) {
      const toLeft = Math.hypot(near.x - left.x, near.y - left.y);
      const toRight = Math.hypot(near.x - right.x, near.y - right.y);
      if (toLeft >= toRight) b = near;
      else a = near;
    }
    const length = Math.hypot(b.x - a.x, b.y - a.y);
    let nx = -(b.y - a.y);
    let ny = b.x - a.x;
    const mx = (a.x + b.x) / 2;
    const my = (a.y + b.y) / 2;
    if (nx * (mx - lens.x) + ny * (my - lens.y) < 0) {
      nx = -nx;
      ny = -ny;
    }
    const norm = Math.max(1e-9, Math.hypot(nx, ny));
    centre = { x: mx + (nx / norm) * (length / 2), y: my + (ny / norm) * (length / 2) };
    widthM = length;
  } else {
    const depth = nearDepth + span / 2;
    centre = { x: lens.x + depth * Math.cos(midBearing), y: lens.y + depth * Math.sin(midBearing) };
    widthM = span;
  }
  // The height: where the top row's ray passes above the near point.
  const top = pixelRay(projection, nearCol, box.top);
  const horizontal = Math.max(1e-9, Math.hypot(top.x, top.y));
  const heightM = Math.max(0, projection.camera.heightM + (top.z / horizontal) * nearDepth);
  const partial: SeenObject['partial'] = [];
  if (box.bottom >= height - 1) partial.push('base');
  if (box.left <= 0 || box.right >= width - 1) partial.push('side');
  if (box.top <= 0) partial.push('top');
  const kindWord = detection.kind === 'unknown' ? 'object' : detection.kind;
  return {
    colour: detection.colour,
    kind: detection.kind,
    label: `${detection.colour} ${kindWord}`,
    bearingDeg: (Math.atan2(centre.y, centre.x) * 180) / Math.PI,
    distanceM: Math.hypot(centre.x, centre.y),
    nearDistanceM: Math.hypot(near.x, near.y),
    widthM,
    heightM,
    confidence: detection.confidence,
    robot: centre,
    world: toWorld(pose, centre),
    image: { ...box },
    partial,
    detector: detection.detector,
  };
}
