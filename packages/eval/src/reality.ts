import { BodyErrorSchema } from '@hal/simulation';
import type { BodyErrorInput } from '@hal/simulation';
import { z } from 'zod';

/**
 * Reality knobs: what separates a perfect simulator from a real robot on a real link and real
 * wheels. All off by default; all seeded (the same seed loses the same calls and draws the same
 * noise), so a run with knobs is as repeatable as one without. The wheel and odometry knobs are
 * the simulator's body error (`bodyError` of @hal/simulation): the world moves the robot where
 * its body really goes, and the checks judge that, while the robot reports its odometry. Their
 * limits are the body error's own.
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
    wheelDiameterErrorPct: BodyErrorSchema.shape.wheelDiameterErrorPct.describe(
      "Standard deviation of each wheel's true diameter from the nominal, percent (the body goes farther or shorter than its odometry says)",
    ),
    wheelSlipPct: BodyErrorSchema.shape.wheelSlipPct.describe(
      'Most ground travel a wheel loses to slip in one motion, percent (uniform from 0 per motion and wheel)',
    ),
    odometryNoisePct: BodyErrorSchema.shape.odometryNoisePct.describe(
      "Standard deviation of the odometry's error on each wheel's travel per motion, percent (the reported pose drifts from the true one)",
    ),
  })
  .strict();
export type Reality = z.output<typeof RealitySchema>;
export type RealityInput = z.input<typeof RealitySchema>;

/** The simulator's body error for these knobs and this trial's seed (undefined when all off). */
export function bodyErrorOf(reality: Reality, seed: number): BodyErrorInput | undefined {
  const { wheelDiameterErrorPct, wheelSlipPct, odometryNoisePct } = reality;
  if (wheelDiameterErrorPct === 0 && wheelSlipPct === 0 && odometryNoisePct === 0) return undefined;
  return { wheelDiameterErrorPct, wheelSlipPct, odometryNoisePct, seed };
}

/**
 * The knobs a trial runs with: each the higher of the run's and the task's, so a task's harder
 * conditions hold in every run and a run's knobs make every task at least that hard.
 */
export function trialReality(run: RealityInput | undefined, task: Reality | undefined): Reality {
  const mine = RealitySchema.parse(run ?? {});
  if (task === undefined) return mine;
  const harder = { ...mine };
  for (const key of Object.keys(mine) as (keyof Reality)[])
    harder[key] = Math.max(mine[key], task[key]);
  return harder;
}
