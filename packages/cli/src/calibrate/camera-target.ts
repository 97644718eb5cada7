// Finds the calibration target in the robot's camera frames with perception's own colour
// segmentation: the region of the target's colour nearest the image's middle column, and the row
// where its base meets the floor (the row perception places objects by). A frame or two teach
// the floor's look first; the base row is the median over the frames that show it.
import { ColourDetector, FramePerceiver } from '@hal/perception';
import type { ColourName, Detection, Detector, DetectorInput } from '@hal/perception';
import { HalError, withTimeout } from '@hal/types';
import type { CameraModel, HardwareAbstractionLayer } from '@hal/types';
import { CliError } from '../cli-error.js';

/** Where the target's base was seen. */
export interface TargetInImage {
  /** The row of the base's lower edge (the first floor row below it), pixels (a median). */
  row: number;
  /** The column of the base's nearest point, pixels. */
  column: number;
  /** How many frames showed the target's base. */
  frames: number;
}

/** Hands perception's colour detections over as well as returning them. */
class KeepingDetector implements Detector {
  readonly name = 'colour';
  readonly #inner = new ColourDetector();
  last: Detection[] = [];
  async detect(input: DetectorInput): Promise<Detection[]> {
    this.last = await this.#inner.detect(input);
    return this.last;
  }
}

/** The base's lowest row and the middle column of the columns at it, as perception takes them. */
function baseOf(detection: Detection): { row: number; column: number } | undefined {
  const rows = detection.baseRows;
  if (rows === undefined) return undefined;
  let row = -1;
  for (const r of rows) row = Math.max(row, r);
  if (row < 0) return undefined;
  let sum = 0;
  let n = 0;
  rows.forEach((r, c) => {
    if (r === row) {
      sum += detection.box.left + c + 0.5;
      n += 1;
    }
  });
  return { row, column: sum / n };
}

const median = (values: number[]) => {
  const sorted = [...values].sort((a, b) => a - b);
  const mid = Math.floor(sorted.length / 2);
  return sorted.length % 2 === 1 ? sorted[mid]! : (sorted[mid - 1]! + sorted[mid]!) / 2;
};

/**
 * Captures `frames` frames from `hal` (each within `timeoutMs`) and finds the `colour` target in
 * them. NOT_FOUND when no frame shows it; FAILED when it is cut by the image's bottom edge (too
 * near: its base is not in view) or its base is hidden in every frame.
 */
export async function findTarget(
  hal: HardwareAbstractionLayer,
  camera: CameraModel,
  colour: ColourName,
  { frames = 5, timeoutMs = 5000 }: { frames?: number; timeoutMs?: number } = {},
): Promise<TargetInImage> {
  const detector = new KeepingDetector();
  const perceiver = new FramePerceiver({ camera, detector });
  const bases: Array<{ row: number; column: number }> = [];
  let seen = 0;
  let cut = 0;
  const pose = { x: 0, y: 0, yaw: 0 };
  for (let i = 0; i < frames; i += 1) {
    const frame = await withTimeout(hal.vision.captureFrame(), timeoutMs);
    if (frame === undefined) {
      throw new HalError('TIMEOUT', `the camera gave no frame within ${timeoutMs} ms`);
    }
    await perceiver.perceive(frame.value, pose);
    const mine = detector.last.filter((d) => d.colour === colour);
    if (mine.length === 0) continue;
    seen += 1;
    // the one straight ahead: its box's middle nearest the image's middle column
    const middle = (d: Detection) =>
      Math.abs((d.box.left + d.box.right + 1) / 2 - camera.width / 2);
    const target = mine.reduce((a, b) => (middle(b) < middle(a) ? b : a));
    if (target.box.bottom >= camera.height - 1) {
      cut += 1;
      continue;
    }
    const base = baseOf(target);
    if (base !== undefined) bases.push(base);
  }
  if (bases.length === 0) {
    const reason =
      seen === 0
        ? `no ${colour} target in ${frames} frames: is it in view, straight ahead, lit, and ${colour}?`
        : cut > 0
          ? `the ${colour} target is cut by the bottom of the image, so its base is out of view: move it farther away`
          : `the ${colour} target's base is hidden in every frame: it must stand on open floor`;
    throw new CliError(seen === 0 ? 'NOT_FOUND' : 'FAILED', `camera calibration: ${reason}`);
  }
  return {
    row: median(bases.map((b) => b.row)),
    column: median(bases.map((b) => b.column)),
    frames: bases.length,
  };
}
