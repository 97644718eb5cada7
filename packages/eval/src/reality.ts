import { z } from 'zod';

/**
 * Reality knobs: what separates a perfect simulator from a real robot on a real link. All off by
 * default; all seeded (the same seed loses the same calls and draws the same noise), so a run
 * with knobs is as repeatable as one without.
 */
export const RealitySchema = z
  .object({
    latencyMs: z
      .number()
      .min(0)
      .max(10_000)
      .default(0)
      .describe('Added before every call runs, simulated milliseconds (the robot waits too)'),
    lossRate: z
      .number()
      .min(0)
      .max(0.9)
      .default(0)
      .describe(
        'Chance that a call is lost: it answers TIMEOUT and nothing runs (stop and e-stop never are)',
      ),
    rangeNoiseM: z
      .number()
      .min(0)
      .max(1)
      .default(0)
      .describe('Standard deviation of Gaussian noise on range readings, metres'),
  })
  .strict();
export type Reality = z.output<typeof RealitySchema>;
export type RealityInput = z.input<typeof RealitySchema>;
