import { renderRobotView } from '../camera.js';
import type { CameraOptions } from '../camera.js';
import { encodeJpeg, jpegDataUrl } from '../jpeg.js';
import type { JpegEncoder } from '../jpeg-encoders.js';
import type { FrameSource } from './options.js';

/**
 * Frames from the built-in software renderer (works in Node), encoded with `encoder` (default:
 * the fastest the runtime has, see `defaultJpegEncoder`).
 */
export const softwareFrameSource =
  (options: CameraOptions, encoder?: JpegEncoder): FrameSource =>
  async (world, robot) =>
    jpegDataUrl(await encodeJpeg(renderRobotView(world, robot, options), 85, encoder));
