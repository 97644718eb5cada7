// The camera's tilt (and, from two or more distances, its lens height) fitted so that a target's
// base row in the image projects to the distance measured on the floor: the inverse of the
// camera model's projection (@hal/kinematics), solved numerically so that it holds for any
// column and any model, exactly as perception projects.
import { cameraProjection, floorPointOfPixel } from '@hal/kinematics';
import { CameraModelSchema, HalError } from '@hal/types';
import type { CameraModel } from '@hal/types';

/** One sighting of the target: where its base met the floor in the image, and how far it was. */
export interface TargetSighting {
  /** Measured distance from the robot's centre to the target's near face (straight ahead), m. */
  distanceM: number;
  /** The image row of the base's lower edge (the first floor row below the target), pixels. */
  row: number;
  /** The image column of the base's nearest point, pixels. */
  column: number;
}

/** A fitted camera model and how well it fits. */
export interface CameraFit {
  model: CameraModel;
  /** Whether the lens height was fitted too (two or more distances), else taken from the model. */
  fittedHeight: boolean;
  /** Per sighting, the distance the fitted model projects its base row to, m. */
  predictedM: number[];
  /** The largest |predicted - measured| over the sightings, m. */
  residualM: number;
}

const TILT = CameraModelSchema.shape.tiltDeg;
/** The schema's tilt range, degrees. */
export const TILT_RANGE_DEG = { min: -45, max: 80 } as const;
/** Lens heights searched when the height is fitted, m. */
const HEIGHT_RANGE_M = { min: 0.01, max: 1 } as const;

/** The forward distance (robot frame x) the pixel's floor point has under `model`; +inf above the horizon. */
function forwardOf(model: CameraModel, sighting: TargetSighting): number {
  const point = floorPointOfPixel(cameraProjection(model), sighting.column, sighting.row);
  return point === undefined ? Number.POSITIVE_INFINITY : point.x;
}

/**
 * The tilt (degrees) that puts `sighting`'s base row at its distance, or undefined when no tilt
 * in the schema's range does. More tilt looks nearer, so the projected distance falls as the tilt
 * rises: a bisection.
 */
export function tiltFor(model: CameraModel, sighting: TargetSighting): number | undefined {
  const error = (tiltDeg: number) =>
    forwardOf({ ...model, tiltDeg }, sighting) - sighting.distanceM;
  let lo: number = TILT_RANGE_DEG.min;
  let hi: number = TILT_RANGE_DEG.max;
  if (error(lo) < 0 || error(hi) > 0) return undefined;
  for (let i = 0; i < 60; i += 1) {
    const mid = (lo + hi) / 2;
    if (error(mid) > 0) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

function evaluate(model: CameraModel, sightings: readonly TargetSighting[], fittedHeight: boolean) {
  const predictedM = sightings.map((s) => forwardOf(model, s));
  const residualM = Math.max(...predictedM.map((p, i) => Math.abs(p - sightings[i]!.distanceM)));
  return { model, fittedHeight, predictedM, residualM };
}

/** The tilt fitting every sighting best at lens height `heightM`: the mean of each one's tilt. */
function fitTilt(
  model: CameraModel,
  sightings: readonly TargetSighting[],
): { model: CameraModel; residualM: number } | undefined {
  const tilts = sightings.map((s) => tiltFor(model, s));
  if (tilts.some((t) => t === undefined)) return undefined;
  const tiltDeg = (tilts as number[]).reduce((a, b) => a + b, 0) / tilts.length;
  const fitted = { ...model, tiltDeg };
  return { model: fitted, residualM: evaluate(fitted, sightings, false).residualM };
}

/**
 * Fits the camera's tilt to `sightings` (at `model`'s lens height), and its lens height as well
 * when they were taken at two or more distances at least 10 cm apart (unless `keepHeight`). RANGE_EXCEEDED when no
 * tilt in the schema's range puts a base row at its distance (a wrong distance, a target that is
 * not on the floor straight ahead).
 */
export function fitCamera(
  model: CameraModel,
  sightings: readonly TargetSighting[],
  { keepHeight = false }: { keepHeight?: boolean } = {},
): CameraFit {
  if (sightings.length === 0) {
    throw new HalError('INVALID_PARAMETER', 'no sightings of the target to fit the camera to');
  }
  const distances = sightings.map((s) => s.distanceM);
  const fitHeight = !keepHeight && Math.max(...distances) - Math.min(...distances) >= 0.1;
  let best = fitTilt(model, sightings);
  if (fitHeight) {
    // the residual over lens heights: a coarse scan, then a finer one around its least
    let step = 0.005;
    let from: number = HEIGHT_RANGE_M.min;
    let to: number = HEIGHT_RANGE_M.max;
    for (let pass = 0; pass < 3; pass += 1) {
      for (let h = from; h <= to + 1e-12; h += step) {
        const fit = fitTilt({ ...model, heightM: h }, sightings);
        if (fit !== undefined && (best === undefined || fit.residualM < best.residualM)) best = fit;
      }
      const centre = best?.model.heightM ?? model.heightM;
      from = Math.max(HEIGHT_RANGE_M.min, centre - step);
      to = Math.min(HEIGHT_RANGE_M.max, centre + step);
      step /= 20;
    }
  }
  if (best === undefined) {
    throw new HalError(
      'RANGE_EXCEEDED',
      `no camera tilt in ${TILT_RANGE_DEG.min}..${TILT_RANGE_DEG.max} degrees puts the target's base ` +
        `at ${distances.map((d) => `${(d * 100).toFixed(1)} cm`).join(' and ')}: ` +
        'check the distance (robot centre to the target near face) and that the target stands on the floor straight ahead',
      { details: { parameter: 'tiltDeg', min: TILT_RANGE_DEG.min, max: TILT_RANGE_DEG.max } },
    );
  }
  const checked = TILT.safeParse(best.model.tiltDeg);
  if (!checked.success) {
    throw new HalError('RANGE_EXCEEDED', `the fitted tilt ${best.model.tiltDeg} is out of range`);
  }
  // far below what a tape measure reads: no more digits than these are kept
  const rounded = CameraModelSchema.parse({
    ...best.model,
    tiltDeg: Math.round(best.model.tiltDeg * 1e4) / 1e4,
    heightM: Math.round(best.model.heightM * 1e5) / 1e5,
  });
  return evaluate(rounded, sightings, fitHeight);
}
