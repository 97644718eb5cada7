import type { CameraProjection } from '@hal/kinematics';
import type { FloorModel } from './floor-model.js';
import type { RgbaImage } from './image.js';
import type { Detection } from './project-object.js';

/** What a detector is given: the decoded frame, its JPEG, and what perception knows of it. */
export interface DetectorInput {
  image: RgbaImage;
  /** The frame as it came (a `data:image/jpeg;base64,...` URL). */
  frame: string;
  projection: CameraProjection;
  /** The floor's learnt appearance (for telling where an object's base meets the floor). */
  floor: FloorModel;
  /** One byte a pixel: the palette label (0 none, 1..6 a palette colour, 7 off-palette). */
  labels: Uint8Array;
}

/**
 * Finds objects in a frame. Perception places what it finds on the floor through the camera
 * model, the same for every detector.
 */
export interface Detector {
  /** Its name, reported with each object ("colour", "vlm:MODEL"). */
  readonly name: string;
  detect(input: DetectorInput): Detection[] | Promise<Detection[]>;
}
