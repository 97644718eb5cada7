import { z } from 'zod';

/**
 * The robot's camera as a pinhole: image size, horizontal field of view (square pixels, the
 * principal point at the image centre), where the lens sits on the robot and how far it looks
 * down. One definition: the simulator renders with it and perception projects with it, so the
 * simulated camera is the robot's camera. Robot frame REP-103 (x forward, y left, z up), metres.
 */
export const CameraModelSchema = z
  .object({
    width: z.number().int().min(16).max(4096).default(320).describe('Image width, pixels'),
    height: z.number().int().min(16).max(4096).default(240).describe('Image height, pixels'),
    fieldOfViewDeg: z
      .number()
      .gt(5)
      .lt(170)
      .default(62)
      .describe('Horizontal field of view, degrees (the OV2640 standard lens: 62)'),
    heightM: z
      .number()
      .gt(0)
      .max(2)
      .default(0.09)
      .describe('Height of the lens above the floor, metres'),
    forwardM: z
      .number()
      .min(-1)
      .max(1)
      .default(0.05)
      .describe("Lens position ahead of the robot's centre, metres"),
    leftM: z
      .number()
      .min(-1)
      .max(1)
      .default(0)
      .describe("Lens position left of the robot's centre, metres"),
    tiltDeg: z
      .number()
      .min(-45)
      .max(80)
      .default(20)
      .describe('How far the camera looks down from level, degrees (down is positive)'),
  })
  .strict();

/** A camera model: see {@link CameraModelSchema}. */
export type CameraModel = z.output<typeof CameraModelSchema>;

/**
 * The V1 cube's camera: the ESP32-CAM's OV2640 at QVGA (320x240, 62 degrees across), its lens
 * 9 cm above the floor and 5 cm ahead of the centre, looking 20 degrees down so that the floor
 * from 7 cm in front of the body to the horizon is in view.
 */
export const V1_CAMERA: Readonly<CameraModel> = Object.freeze(CameraModelSchema.parse({}));

/** A camera model from partial settings (the rest V1's), checked: throws a ZodError when invalid. */
export function cameraModel(settings: Partial<CameraModel> = {}): CameraModel {
  return CameraModelSchema.parse({ ...V1_CAMERA, ...settings });
}
