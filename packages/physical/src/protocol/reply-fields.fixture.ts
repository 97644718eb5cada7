import { fc } from '@fast-check/vitest';

// Well-formed values of the reply fields, shared by the property tests of the reply schemas and
// of the hand-checked reply path.

export const int = fc.integer();
export const byte = fc.integer({ min: 0, max: 255 });
export const uint32 = fc.integer({ min: 0, max: 4_294_967_295 });
export const finite = fc.double({ noNaN: true, noDefaultInfinity: true });

/** The optional fields of a motion command's reply (beside its required `move_id`). */
export const motionReplyFields = {
  left_steps: int,
  right_steps: int,
  speed: finite,
  speed_clamped: fc.boolean(),
  duration_ms: int,
  duration_us: int,
  left_sps: finite,
  right_sps: finite,
  running: fc.boolean(),
};
