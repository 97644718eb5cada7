import type { BodyScales, MotionScales, WheelScale } from '@hal/kinematics';
import { HalError } from '@hal/types';
import { z } from 'zod';
import { SeededRandom } from '../rng.js';

/*
 * How the simulated body differs from the robot its firmware believes it is: wheels whose true
 * diameter is not the nominal one, wheels that slip on the ground, and odometry that counts each
 * wheel's travel with an error. With any of them the ground truth (where the world has the robot:
 * contacts, sensors, the camera) moves differently from the pose the robot reports (its
 * odometry: `getPose`, the pose in motion results, what `moveTo` plans from). All off by default,
 * and then the two are the same pose. Seeded: the same seed and the same commands give the same
 * errors.
 */
export const BodyErrorSchema = z
  .object({
    wheelDiameterErrorPct: z
      .number()
      .min(0)
      .max(20)
      .default(0)
      .describe(
        "Standard deviation of each wheel's true diameter from the nominal, percent; drawn once per robot",
      ),
    wheelSlipPct: z
      .number()
      .min(0)
      .max(50)
      .default(0)
      .describe(
        'Most ground travel a wheel loses to slip in one motion, percent; drawn per motion and wheel, uniformly from 0',
      ),
    odometryNoisePct: z
      .number()
      .min(0)
      .max(20)
      .default(0)
      .describe(
        "Standard deviation of the odometry's error on each wheel's travel, percent; drawn per motion and wheel",
      ),
    seed: z.number().int().min(0).max(0xffffffff).default(1).describe('Seed of the errors drawn'),
  })
  .strict();
export type BodyError = z.output<typeof BodyErrorSchema>;
export type BodyErrorInput = z.input<typeof BodyErrorSchema>;

/** Checks a body error; INVALID_PARAMETER naming the field (`"bodyError.wheelSlipPct" ...`). */
export function parseBodyError(input: BodyErrorInput = {}): BodyError {
  const parsed = BodyErrorSchema.safeParse(input);
  if (parsed.success) return parsed.data;
  const issue = parsed.error.issues[0];
  const field = ['bodyError', ...(issue?.path.map(String) ?? [])].join('.');
  throw new HalError('INVALID_PARAMETER', `"${field}" ${issue?.message ?? 'is invalid'}`, {
    details: { field },
  });
}

/** Whether any error is switched on. */
export function hasBodyError(error: BodyError): boolean {
  return error.wheelDiameterErrorPct > 0 || error.wheelSlipPct > 0 || error.odometryNoisePct > 0;
}

/**
 * Draws the errors of one robot: its wheels' diameters once, and at each motion the slip and the
 * odometry's error. Four numbers are drawn per motion whatever is on, so switching one knob on
 * does not change the draws of another.
 */
export class BodyErrorModel implements BodyScales {
  readonly options: BodyError;
  readonly diameter: WheelScale;
  readonly #random: SeededRandom;

  constructor(options: BodyErrorInput) {
    this.options = parseBodyError(options);
    this.#random = new SeededRandom(this.options.seed);
    const sigma = this.options.wheelDiameterErrorPct / 100;
    // at most 3 sigma either way: a wheel never shrinks to nothing
    const draw = () => 1 + Math.max(-3 * sigma, Math.min(3 * sigma, this.#random.gaussian(sigma)));
    this.diameter = { left: draw(), right: draw() };
  }

  /** The scales of the next motion. */
  nextMotion(): MotionScales {
    const slip = this.options.wheelSlipPct / 100;
    const noise = this.options.odometryNoisePct / 100;
    const slipLeft = this.#random.next() * slip;
    const slipRight = this.#random.next() * slip;
    const clip = (v: number) => Math.max(-3 * noise, Math.min(3 * noise, v));
    const noiseLeft = clip(this.#random.gaussian(noise));
    const noiseRight = clip(this.#random.gaussian(noise));
    return {
      truth: {
        left: this.diameter.left * (1 - slipLeft),
        right: this.diameter.right * (1 - slipRight),
      },
      reported: { left: 1 + noiseLeft, right: 1 + noiseRight },
    };
  }
}
