// The alternative a user would pick for perception's image work: OpenCV.js (WASM,
// @techstark/opencv-js 4.12), used the way its documentation shows, Mats allocated once and
// reused. The same steps as @hal/perception's hand-written ones: classify every pixel into the
// palette's colours (cvtColor to HSV, inRange per colour band: the palette's hue bands and
// saturation and value floors), connected regions per colour with their boxes and the lowest row
// per column (connectedComponentsWithStats), and per column the first row from the bottom that is
// not floor (the floor's colour histogram from the image's bottom rows, calcBackProject, a
// vertical run of two, reduce). OpenCV.js has no JPEG decoder in its JavaScript build, so the
// caller decodes.
import cvModule from '@techstark/opencv-js';
import type { Mat } from '@techstark/opencv-js';
import { COLOUR_NAMES, DEFAULT_COLOUR_THRESHOLDS, DEFAULT_PALETTE } from '@hal/perception';
import type { ColourName, RgbaImage } from '@hal/perception';

type OpenCv = typeof cvModule;

/** A connected region of one colour. */
export interface CvRegion {
  colour: ColourName;
  left: number;
  top: number;
  width: number;
  height: number;
  area: number;
  /** Per column of the box, the lowest row of the region (-1 where it has none). */
  bottoms: Int16Array;
}

/** What the OpenCV pipeline found in a frame. */
export interface CvResult {
  regions: CvRegion[];
  /** Per image column, the first row from the bottom that is not floor, or -1. */
  firstObstacleRow: Int16Array;
}

const MIN_AREA = 20;
/** cv.REDUCE_MAX, which the package's type declarations leave out. */
const REDUCE_MAX = 2;
const FLOOR_ROWS = 16;
const RUN = 2;

/**
 * Loads OpenCV.js (its WASM runtime initialises asynchronously). The module is itself a
 * "thenable" that resolves to itself, so it is handed back wrapped: awaiting or returning it
 * from an async function would never settle.
 */
export async function loadOpenCv(): Promise<{ cv: OpenCv }> {
  const cv = cvModule as OpenCv & { onRuntimeInitialized?: () => void; Mat?: unknown };
  if (typeof cv.Mat !== 'function') {
    await new Promise<void>((resolve, reject) => {
      const timer = setTimeout(
        () => reject(new Error('OpenCV.js did not initialise in 60 s')),
        60_000,
      );
      cv.onRuntimeInitialized = () => {
        clearTimeout(timer);
        resolve();
      };
    });
  }
  return { cv };
}

/** The palette's hue bands in OpenCV's 8-bit HSV (hue 0..179): [label, low, high]. */
function hueBands(): Array<[number, number, number]> {
  const bands: Array<[number, number, number]> = [];
  for (const colour of DEFAULT_PALETTE) {
    const label = COLOUR_NAMES.indexOf(colour.name);
    const low = Math.ceil((colour.hueDeg - colour.toleranceDeg) / 2);
    const high = Math.floor((colour.hueDeg + colour.toleranceDeg) / 2);
    if (low < 0) {
      bands.push([label, 180 + low, 179], [label, 0, high]);
    } else {
      bands.push([label, low, Math.min(179, high)]);
    }
  }
  return bands;
}

/** Lowest row per column of region `id` in `labels`, within its box. */
function lowestRows(
  labels: Int32Array,
  width: number,
  id: number,
  left: number,
  top: number,
  w: number,
  h: number,
): Int16Array {
  const out = new Int16Array(w).fill(-1);
  for (let c = 0; c < w; c += 1) {
    for (let r = top + h - 1; r >= top; r -= 1) {
      if (labels[r * width + left + c] === id) {
        out[c] = r;
        break;
      }
    }
  }
  return out;
}

/** The pipeline for frames of one size, its Mats allocated once. */
export class OpenCvPipeline {
  readonly #cv: OpenCv;
  readonly #width: number;
  readonly #height: number;
  readonly #rgba: Mat;
  readonly #rgb: Mat;
  readonly #hsv: Mat;
  readonly #tmp: Mat;
  readonly #masks: Mat[];
  readonly #bounds: Array<{ label: number; low: Mat; high: Mat }>;
  readonly #labels: Mat;
  readonly #stats: Mat;
  readonly #centroids: Mat;
  readonly #hist: Mat;
  readonly #back: Mat;
  readonly #notFloor: Mat;
  readonly #eroded: Mat;
  readonly #ramp: Mat;
  readonly #rowMax: Mat;
  readonly #kernel: Mat;
  readonly #noMask: Mat;

  constructor(cv: OpenCv, width: number, height: number) {
    this.#cv = cv;
    this.#width = width;
    this.#height = height;
    const { CV_8UC1, CV_8UC3, CV_8UC4 } = cv;
    this.#rgba = new cv.Mat(height, width, CV_8UC4);
    this.#rgb = new cv.Mat(height, width, CV_8UC3);
    this.#hsv = new cv.Mat(height, width, CV_8UC3);
    this.#tmp = new cv.Mat(height, width, CV_8UC1);
    this.#masks = COLOUR_NAMES.map(() => new cv.Mat(height, width, CV_8UC1));
    const sMin = Math.ceil(DEFAULT_COLOUR_THRESHOLDS.minSaturation * 255);
    const vMin = Math.ceil(DEFAULT_COLOUR_THRESHOLDS.minValue * 255);
    this.#bounds = hueBands().map(([label, low, high]) => ({
      label,
      low: new cv.Mat(height, width, CV_8UC3, new cv.Scalar(low, sMin, vMin, 0)),
      high: new cv.Mat(height, width, CV_8UC3, new cv.Scalar(high, 255, 255, 0)),
    }));
    this.#labels = new cv.Mat();
    this.#stats = new cv.Mat();
    this.#centroids = new cv.Mat();
    this.#hist = new cv.Mat();
    this.#back = new cv.Mat();
    this.#notFloor = new cv.Mat();
    this.#eroded = new cv.Mat();
    this.#ramp = new cv.Mat(height, width, CV_8UC1);
    for (let y = 0; y < height; y += 1) this.#ramp.data.fill(y + 1, y * width, (y + 1) * width);
    this.#rowMax = new cv.Mat();
    this.#kernel = cv.Mat.ones(RUN, 1, cv.CV_8U);
    this.#noMask = new cv.Mat();
  }

  /** Classifies, labels and scans the floor of a decoded RGBA frame. */
  run(image: RgbaImage): CvResult {
    const cv = this.#cv;
    const width = this.#width;
    const height = this.#height;
    this.#rgba.data.set(image.data);
    cv.cvtColor(this.#rgba, this.#rgb, cv.COLOR_RGBA2RGB);
    cv.cvtColor(this.#rgb, this.#hsv, cv.COLOR_RGB2HSV);
    for (const mask of this.#masks) mask.data.fill(0);
    for (const { label, low, high } of this.#bounds) {
      cv.inRange(this.#hsv, low, high, this.#tmp);
      const mask = this.#masks[label];
      if (mask !== undefined) cv.bitwise_or(mask, this.#tmp, mask);
    }
    const regions: CvRegion[] = [];
    this.#masks.forEach((mask, k) => {
      if (cv.countNonZero(mask) === 0) return;
      const n = cv.connectedComponentsWithStats(
        mask,
        this.#labels,
        this.#stats,
        this.#centroids,
        8,
        cv.CV_32S,
      );
      const s = this.#stats.data32S;
      const labels = this.#labels.data32S;
      for (let l = 1; l < n; l += 1) {
        const left = s[l * 5] ?? 0;
        const top = s[l * 5 + 1] ?? 0;
        const w = s[l * 5 + 2] ?? 0;
        const h = s[l * 5 + 3] ?? 0;
        const area = s[l * 5 + 4] ?? 0;
        if (area < MIN_AREA) continue;
        regions.push({
          colour: COLOUR_NAMES[k] ?? 'red',
          left,
          top,
          width: w,
          height: h,
          area,
          bottoms: lowestRows(labels, width, l, left, top, w, h),
        });
      }
    });
    // Floor: a 16x16x16 RGB histogram of the bottom rows, back-projected onto the frame.
    const ref = this.#rgb.roi(new cv.Rect(0, height - FLOOR_ROWS, width, FLOOR_ROWS));
    const refVec = new cv.MatVector();
    refVec.push_back(ref);
    cv.calcHist(
      refVec,
      [0, 1, 2],
      this.#noMask,
      this.#hist,
      [16, 16, 16],
      [0, 256, 0, 256, 0, 256],
    );
    const all = new cv.MatVector();
    all.push_back(this.#rgb);
    cv.calcBackProject(all, [0, 1, 2], this.#hist, this.#back, [0, 256, 0, 256, 0, 256], 1);
    cv.threshold(this.#back, this.#notFloor, 2, 255, cv.THRESH_BINARY_INV);
    cv.erode(
      this.#notFloor,
      this.#eroded,
      this.#kernel,
      new cv.Point(0, RUN - 1),
      1,
      cv.BORDER_CONSTANT,
      cv.morphologyDefaultBorderValue(),
    );
    cv.bitwise_and(this.#eroded, this.#ramp, this.#eroded);
    cv.reduce(this.#eroded, this.#rowMax, 0, REDUCE_MAX, cv.CV_8U);
    const firstObstacleRow = new Int16Array(width);
    for (let x = 0; x < width; x += 1) firstObstacleRow[x] = (this.#rowMax.data[x] ?? 0) - 1;
    ref.delete();
    refVec.delete();
    all.delete();
    return { regions, firstObstacleRow };
  }
}
