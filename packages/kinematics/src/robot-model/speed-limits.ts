import { HalError } from '@hal/types';

/**
 * Throws INVALID_PARAMETER unless `value` is a finite number (and > 0 when `positive`): the
 * firmware's JSON reader refuses non-finite numbers, so the simulated robot does too, before it
 * changes anything.
 */
export function requireFinite(
  field: string,
  value: number,
  options: { positive?: boolean; max?: number } = {},
): void {
  if (typeof value !== 'number' || !Number.isFinite(value)) {
    throw new HalError('INVALID_PARAMETER', `"${field}" must be a finite number, got ${value}`, {
      details: { field, value: String(value) },
    });
  }
  if (options.positive === true && !(value > 0)) {
    throw new HalError('RANGE_EXCEEDED', `"${field}" must be greater than 0, got ${value}`, {
      details: { field, min: 0, value },
    });
  }
  if (options.max !== undefined && value > options.max) {
    throw new HalError(
      'RANGE_EXCEEDED',
      `"${field}" must be at most ${options.max}, got ${value}`,
      {
        details: { field, max: options.max, value },
      },
    );
  }
}

/** The longest `drive` the firmware accepts, ms (cube_motion_commands.cpp). */
export const MAX_DRIVE_DURATION_MS = 600_000;

/** Wheel speed limits the firmware applies to a requested cruise speed, steps/s. */
export function clampSpeed(
  requested: number | undefined,
  max: number,
): { speed: number; clamped: boolean } {
  if (requested === undefined) return { speed: max, clamped: false };
  if (!Number.isFinite(requested) || requested <= 0) {
    throw new HalError('RANGE_EXCEEDED', `"speed" must be 1..${max} steps/s, got ${requested}`, {
      details: { field: 'speed', min: 1, max, value: requested },
    });
  }
  if (requested > max) return { speed: max, clamped: true };
  if (requested < 1) return { speed: 1, clamped: true };
  return { speed: requested, clamped: false };
}

/**
 * Drive speeds as the firmware applies them: whole signed steps/s (truncated toward zero), both
 * scaled by the same factor (truncated again) when the faster exceeds `max`.
 */
export function clampDriveSpeeds(
  leftSps: number,
  rightSps: number,
  max: number,
): { left: number; right: number; clamped: boolean } {
  let left = Math.trunc(leftSps);
  let right = Math.trunc(rightSps);
  const fastest = Math.max(Math.abs(left), Math.abs(right));
  if (fastest > max) {
    left = Math.trunc((left * max) / fastest);
    right = Math.trunc((right * max) / fastest);
    return { left, right, clamped: true };
  }
  return { left, right, clamped: false };
}
