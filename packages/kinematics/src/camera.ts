import type { CameraModel } from '@hal/types';

/*
 * The pinhole projection of a camera model (@hal/types' CameraModel): image pixels to rays and
 * floor points in the robot's frame (REP-103: x forward, y left, z up, metres, origin on the floor
 * under the robot's centre) and back. The simulator's renderer casts its rays with these
 * functions and perception inverts them, so the two agree by construction. Image coordinates:
 * (u, v) from the top-left corner of the image; pixel (i, j) covers [i, i+1) x [j, j+1), its
 * centre is (i + 0.5, j + 0.5).
 */

/** A direction or point in the robot's frame, metres. */
export interface Vec3 {
  x: number;
  y: number;
  z: number;
}

/** A point on the floor in the robot's frame, metres. */
export interface FloorPoint {
  x: number;
  y: number;
}

/** A point in the image, pixels from the top-left corner. */
export interface ImagePoint {
  u: number;
  v: number;
}

/** The focal length in pixels (square pixels). */
export function focalLengthPx(camera: CameraModel): number {
  return camera.width / 2 / Math.tan((camera.fieldOfViewDeg * Math.PI) / 360);
}

/** Precomputed terms of a camera model, for the per-pixel loops. */
export interface CameraProjection {
  readonly camera: CameraModel;
  readonly f: number;
  readonly cx: number;
  readonly cy: number;
  readonly cosTilt: number;
  readonly sinTilt: number;
}

/** The projection terms of `camera`. */
export function cameraProjection(camera: CameraModel): CameraProjection {
  const tilt = (camera.tiltDeg * Math.PI) / 180;
  return {
    camera,
    f: focalLengthPx(camera),
    cx: camera.width / 2,
    cy: camera.height / 2,
    cosTilt: Math.cos(tilt),
    sinTilt: Math.sin(tilt),
  };
}

/**
 * The direction (robot frame, not of unit length: its forward component along the optical axis
 * is 1) of the ray through image point (u, v).
 */
export function pixelRay(p: CameraProjection, u: number, v: number): Vec3 {
  const left = -(u - p.cx) / p.f;
  const up = -(v - p.cy) / p.f;
  return {
    x: p.cosTilt + p.sinTilt * up,
    y: left,
    z: -p.sinTilt + p.cosTilt * up,
  };
}

/**
 * Where the ray through image point (u, v) meets the floor, in the robot's frame; undefined when
 * it does not descend (at or above the horizon).
 */
export function floorPointOfPixel(
  p: CameraProjection,
  u: number,
  v: number,
): FloorPoint | undefined {
  const ray = pixelRay(p, u, v);
  if (ray.z >= -1e-9) return undefined;
  const t = p.camera.heightM / -ray.z;
  return { x: p.camera.forwardM + ray.x * t, y: p.camera.leftM + ray.y * t };
}

/** The image point of a point in the robot's frame; undefined when it is behind the lens. */
export function pixelOfPoint(p: CameraProjection, point: Vec3): ImagePoint | undefined {
  const px = point.x - p.camera.forwardM;
  const py = point.y - p.camera.leftM;
  const pz = point.z - p.camera.heightM;
  const ahead = p.cosTilt * px - p.sinTilt * pz;
  if (ahead <= 1e-9) return undefined;
  const up = p.sinTilt * px + p.cosTilt * pz;
  return { u: p.cx - (p.f * py) / ahead, v: p.cy - (p.f * up) / ahead };
}

/** The image row (fractional) of the horizon: rays above it never meet the floor. */
export function horizonRow(p: CameraProjection): number {
  return p.cy - (p.f * p.sinTilt) / p.cosTilt;
}

/**
 * The distance from the robot's centre to the nearest floor the camera sees straight ahead (the
 * bottom edge of the image's middle column), metres: anything nearer is below the image.
 */
export function nearestVisibleFloorM(p: CameraProjection): number {
  const point = floorPointOfPixel(p, p.cx, p.camera.height);
  return point === undefined ? Number.POSITIVE_INFINITY : Math.hypot(point.x, point.y);
}
