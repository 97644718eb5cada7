import { HalError } from '@hal/types';
import type { CameraModel, Logger } from '@hal/types';
import { z } from 'zod';
import type { FramePerceiver } from '../frame-perceiver.js';

/** How the guard watches and when it stops the robot. Robot frame, metres, ms. */
export const GuardSettingsSchema = z.object({
  standoffM: z
    .number()
    .gt(0)
    .max(5)
    .default(0.1)
    .describe("Stop before anything nearer than this ahead of the body's front, metres"),
  bodyRadiusM: z
    .number()
    .gt(0)
    .max(2)
    .default(0.07)
    .describe("From the robot's centre to its front, metres (the V1 footprint: 0.07)"),
  corridorMarginM: z
    .number()
    .min(0)
    .max(1)
    .default(0.02)
    .describe("Added to the body's half width on each side of the corridor watched, metres"),
  sense: z
    .enum(['auto', 'camera', 'range'])
    .default('auto')
    .describe('What to watch with: the range sensors where present, else the camera (auto)'),
  framePeriodMs: z
    .number()
    .gt(0)
    .max(10_000)
    .default(100)
    .describe('How often to look while a motion runs, ms (the camera rate: 10 fps)'),
  blindLimitMs: z
    .number()
    .gt(0)
    .max(60_000)
    .default(1000)
    .describe('Stop a motion when no look has succeeded for this long, ms'),
  lookTimeoutMs: z
    .number()
    .gt(0)
    .max(60_000)
    .default(2000)
    .describe('Longest wait for one look (a frame, a range reading), ms'),
  minLegM: z
    .number()
    .gt(0)
    .max(1)
    .default(0.01)
    .describe('Shortest leg worth driving, metres: less room than this ends the motion'),
  errorFraction: z
    .number()
    .min(0)
    .max(0.9)
    .default(0.1)
    .describe('A leg stops short of the stand-off by this fraction of the distance seen'),
  settleMs: z
    .number()
    .min(0)
    .max(10_000)
    .optional()
    .describe(
      'After a motion ends, wait this long before looking, ms, so the frame shows the robot where ' +
        'it stopped (a camera streams its latest frame). Default 0 in the simulator (it renders ' +
        'on demand), else two frame periods',
    ),
  reverse: z
    .enum(['pass', 'refuse'])
    .default('pass')
    .describe('A reverse, which nothing watches: let it through (warned once) or refuse it'),
  watch: z
    .boolean()
    .default(true)
    .describe('Also look while a leg runs and stop it (off: only between legs)'),
});

/** The guard's settings, every default filled in (see {@link GuardSettingsSchema}). */
export type GuardSettings = z.output<typeof GuardSettingsSchema>;

/** Options of {@link guardHal}: its settings, and what it sees with and writes to. */
export interface GuardOptions extends Partial<GuardSettings> {
  /**
   * The camera (V1's where a field is left out), for a camera-watching guard. Default the one the
   * robot reports (`getDeviceInfo().camera`), else V1's.
   */
  camera?: Partial<CameraModel>;
  /** Builds the frame perceiver (default one on `camera` that detects no objects). */
  perceiver?: () => FramePerceiver;
  /** Where the guard writes (namespace `hal:guard`); default silent. */
  logger?: Logger;
}

/** Checks the settings in `options`; INVALID_PARAMETER naming the first bad one. */
export function guardSettings(options: Partial<GuardSettings> = {}): GuardSettings {
  const picked: Record<string, unknown> = {};
  for (const key of Object.keys(GuardSettingsSchema.shape)) {
    const value = (options as Record<string, unknown>)[key];
    if (value !== undefined) picked[key] = value;
  }
  const parsed = GuardSettingsSchema.safeParse(picked);
  if (parsed.success) return parsed.data;
  const issue = parsed.error.issues[0];
  const name = issue?.path.map(String).join('.') ?? 'options';
  throw new HalError('INVALID_PARAMETER', `"${name}" ${issue?.message ?? 'is invalid'}`, {
    details: { parameter: name },
  });
}
