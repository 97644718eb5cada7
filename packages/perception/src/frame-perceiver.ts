import { cameraProjection } from '@hal/kinematics';
import type { CameraProjection } from '@hal/kinematics';
import type { Pose2D } from '@hal/navigation';
import { cameraModel } from '@hal/types';
import type { CameraModel } from '@hal/types';
import { ColourDetector } from './colour-detector.js';
import { decodeFrame } from './decode.js';
import type { JpegDecoder } from './image.js';
import type { Detector } from './detector.js';
import { FloorModel } from './floor-model.js';
import type { FloorModelOptions } from './floor-model.js';
import { DEFAULT_FREE_SPACE, scanFreeSpace } from './free-space.js';
import type { FreeSpaceColumn, FreeSpaceOptions } from './free-space.js';
import type { RgbaImage } from './image.js';
import { defaultColourTable } from './palette.js';
import { projectDetection } from './project-object.js';
import type { SeenObject } from './seen-object.js';

/** A `data:image/jpeg;base64,...` URL of JPEG bytes (a detector that sends the frame needs it). */
function jpegDataUrl(bytes: Uint8Array): string {
  const B = (globalThis as { Buffer?: { from(b: Uint8Array): { toString(e: 'base64'): string } } })
    .Buffer;
  if (B !== undefined) return `data:image/jpeg;base64,${B.from(bytes).toString('base64')}`;
  let text = '';
  for (let i = 0; i < bytes.length; i += 0x8000) {
    text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  }
  return `data:image/jpeg;base64,${btoa(text)}`;
}

/** What one frame showed. Robot frame REP-103 and the world (odometry) frame, metres. */
export interface Percept {
  /** When the frame was taken, ms since the epoch (the host's clock). */
  capturedAt: number;
  /** The robot's believed (odometry) pose when the frame was taken. */
  pose: Pose2D;
  /** The objects seen, nearest first. */
  objects: SeenObject[];
  /** Per scanned image column, how far the floor is free. */
  freeSpace: FreeSpaceColumn[];
  /** The frame's size, pixels. */
  width: number;
  height: number;
  /** Whether the floor's look had been learnt (false only when nothing was learnt). */
  floorKnown: boolean;
  /** Time spent, ms: decoding, detecting, free space, all. */
  timings: { decodeMs: number; detectMs: number; freeSpaceMs: number; totalMs: number };
}

/** Options of a {@link FramePerceiver}. */
export interface FramePerceiverOptions {
  /** The camera (V1's where a field is left out). */
  camera?: Partial<CameraModel>;
  /** The object detector. Default colour segmentation ({@link ColourDetector}). */
  detector?: Detector;
  /** The JPEG decoder. Default sharp in Node when installed, else jpeg-js. */
  decoder?: JpegDecoder;
  /** How free space is scanned. */
  freeSpace?: Partial<FreeSpaceOptions>;
  /** How the floor's look is learnt. */
  floor?: FloorModelOptions;
}

/**
 * Turns camera frames into objects and free space, through one camera model: the same code for
 * the simulator's rendered frames and the ESP32-CAM's JPEGs. It keeps the floor's learnt look
 * from frame to frame; it calls no HAL (see `Perception` for the one that does).
 */
export class FramePerceiver {
  readonly camera: CameraModel;
  readonly projection: CameraProjection;
  readonly detector: Detector;
  readonly floor: FloorModel;
  readonly #decoder: JpegDecoder | undefined;
  readonly #freeSpace: FreeSpaceOptions;
  #labels = new Uint8Array(0);

  constructor(options: FramePerceiverOptions = {}) {
    this.camera = cameraModel(options.camera);
    this.projection = cameraProjection(this.camera);
    this.detector = options.detector ?? new ColourDetector();
    this.#decoder = options.decoder;
    this.floor = new FloorModel(options.floor);
    this.#freeSpace = { ...DEFAULT_FREE_SPACE, ...options.freeSpace };
    const { maxRangeM, columnStep, minRun } = this.#freeSpace;
    if (!(maxRangeM > 0 && Number.isFinite(maxRangeM)))
      throw new RangeError(`"maxRangeM" must be a positive number, got ${maxRangeM}`);
    if (!(Number.isInteger(columnStep) && columnStep >= 1))
      throw new RangeError(`"columnStep" must be a whole number of 1 or more, got ${columnStep}`);
    if (!(Number.isInteger(minRun) && minRun >= 1))
      throw new RangeError(`"minRun" must be a whole number of 1 or more, got ${minRun}`);
  }

  /** Decodes `frame` (a JPEG data URL, base64 or bytes) and perceives it at `pose`. */
  async perceive(
    frame: string | Uint8Array,
    pose: Pose2D,
    capturedAt = Date.now(),
  ): Promise<Percept> {
    const start = performance.now();
    const image = await decodeFrame(frame, this.#decoder);
    const decodeMs = performance.now() - start;
    const percept = await this.perceiveImage(
      image,
      pose,
      typeof frame === 'string' ? frame : jpegDataUrl(frame),
      capturedAt,
    );
    percept.timings.decodeMs = decodeMs;
    percept.timings.totalMs += decodeMs;
    return percept;
  }

  /** Perceives a decoded image taken at `pose`. */
  async perceiveImage(
    image: RgbaImage,
    pose: Pose2D,
    frame = '',
    capturedAt = Date.now(),
  ): Promise<Percept> {
    const { width, height } = this.camera;
    if (image.width !== width || image.height !== height) {
      throw new RangeError(
        `the frame is ${image.width}x${image.height} but the camera model says ${width}x${height}: ` +
          'set the camera model to the camera (or calibrate it)',
      );
    }
    const start = performance.now();
    if (this.#labels.length !== width * height) this.#labels = new Uint8Array(width * height);
    const labels = this.#labels;
    defaultColourTable().labelImage(image.data, labels);
    this.floor.learn(image, labels);
    const detections = await this.detector.detect({
      image,
      frame,
      projection: this.projection,
      floor: this.floor,
      labels,
    });
    const objects: SeenObject[] = [];
    for (const detection of detections) {
      const object = projectDetection(detection, this.projection, pose);
      if (object !== undefined) objects.push(object);
    }
    objects.sort((a, b) => a.distanceM - b.distanceM);
    const detected = performance.now();
    const freeSpace = scanFreeSpace(image, this.floor, this.projection, this.#freeSpace);
    const done = performance.now();
    return {
      capturedAt,
      pose: { ...pose },
      objects,
      freeSpace,
      width,
      height,
      floorKnown: this.floor.trained,
      timings: {
        decodeMs: 0,
        detectMs: detected - start,
        freeSpaceMs: done - detected,
        totalMs: done - start,
      },
    };
  }
}
