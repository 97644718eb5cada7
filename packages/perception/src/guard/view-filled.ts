import { horizonRow } from '@hal/kinematics';
import type { FramePerceiver } from '../frame-perceiver.js';
import type { RgbaImage } from '../image.js';

/** Share of the band above the horizon that may pass for floor before the view counts as filled. */
const FILLED_SHARE = 0.5;

/**
 * Whether the floor model takes what is above the horizon (where no floor can be) for floor: an
 * obstacle fills the view and was learnt as the floor (a perceiver's first frame is taken to show
 * open floor). The central 60 % of the columns, every other row and column.
 */
export function viewFilled(perceiver: FramePerceiver, image: RgbaImage): boolean {
  const top = Math.min(image.height, Math.floor(horizonRow(perceiver.projection)) - 1);
  if (top < 1) return false;
  const from = Math.floor(image.width * 0.2);
  const to = Math.ceil(image.width * 0.8);
  let seen = 0;
  let floor = 0;
  for (let row = 0; row < top; row += 2) {
    for (let col = from; col < to; col += 2) {
      seen += 1;
      if (perceiver.floor.isFloorAt(image.data, (row * image.width + col) * 4)) floor += 1;
    }
  }
  return seen > 0 && floor / seen > FILLED_SHARE;
}
