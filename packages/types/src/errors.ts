import { z } from 'zod';

/**
 * Every reason a HAL call can fail. The first five are the Tafy HAL codes; the rest are the ones a
 * real robot link needs. Programs branch on these, never on message text.
 */
export const HAL_ERROR_CODES = [
  /** A parameter is missing, of the wrong type, NaN or infinite. */
  'INVALID_PARAMETER',
  /** A parameter is a finite number outside the robot's configured limits. */
  'RANGE_EXCEEDED',
  /** The robot lacks the capability this call needs. */
  'NOT_IMPLEMENTED',
  /** The hardware reported a fault (motor driver, sensor, firmware). */
  'HARDWARE_ERROR',
  /** A wait ran out: a reply, an acknowledgement or the end of a motion never came. */
  'TIMEOUT',
  /** The emergency stop is latched; motion is refused until it is reset. */
  'EMERGENCY_STOPPED',
  /**
   * There is no link to the robot (never connected, or the link was lost). From a motion call or
   * `stop()`, `details.stopConfirmed` says whether the robot acknowledged a stop; `false` means it
   * could not be told to stop, and only its own host timeout (`details.hostTimeoutMs`) stops it.
   */
  'NOT_CONNECTED',
  /** The HAL has not been initialised, or has been cleaned up. */
  'NOT_READY',
  /** The robot touched a wall or an obstacle and stopped. */
  'COLLISION',
  /** A motion was interrupted by `stop()`, a newer motion or a safety trip. */
  'INTERRUPTED',
  /** A message on the wire could not be decoded (bad JSON, bad frame, schema violation). */
  'MALFORMED',
  /** The robot does not know the command it was sent. */
  'UNKNOWN_COMMAND',
  /** The robot refused a request older than the ones it remembers. */
  'STALE_SEQUENCE',
  /** The robot's session changed (it rebooted, or another host connected). */
  'SESSION_MISMATCH',
  /** The request's authentication code was missing or wrong. */
  'AUTH_FAILED',
  /** Another client controls the robot: this one may only watch (read calls, state, e-stop). */
  'NOT_CONTROLLER',
  /**
   * The guard saw an obstacle ahead nearer than its stand-off: the motion was refused before
   * anything moved, or stopped. `details.distanceM` is the free distance seen ahead of the body's
   * front, metres, `details.source` what saw it (`camera` or `range`).
   */
  'OBSTACLE_AHEAD',
] as const;

/** A HAL error code (see {@link HAL_ERROR_CODES}). */
export type HalErrorCode = (typeof HAL_ERROR_CODES)[number];

export const HalErrorCodeSchema = z
  .enum(HAL_ERROR_CODES)
  .describe('Machine-readable reason a call failed');

/** Extra, structured facts about an error: the parameter, the limit, the value received, ... */
export type HalErrorDetails = Record<string, unknown>;

export interface HalErrorOptions {
  details?: HalErrorDetails;
  cause?: unknown;
}

/**
 * The one error class of the library. Thrown inside implementations with a literal code, and
 * converted once, at the HAL boundary, into a failed {@link HALToolResult}.
 */
export class HalError extends Error {
  override readonly name = 'HalError';
  readonly code: HalErrorCode;
  readonly details: HalErrorDetails | undefined;

  constructor(code: HalErrorCode, message: string, options: HalErrorOptions = {}) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.details = options.details;
  }
}

/** True for a {@link HalError}, including one from another copy of this package. */
export function isHalError(value: unknown): value is HalError {
  if (value instanceof HalError) return true;
  if (!(value instanceof Error) || value.name !== 'HalError') return false;
  const code: unknown = (value as Error & { code?: unknown }).code;
  return typeof code === 'string' && (HAL_ERROR_CODES as readonly string[]).includes(code);
}

/** The message of anything thrown: an Error's message, else its string form. */
export function errorMessage(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}

/**
 * Turns anything thrown into a HalError: a HalError passes through, anything else becomes a
 * HARDWARE_ERROR that keeps the original as its cause.
 */
export function toHalError(value: unknown): HalError {
  if (isHalError(value)) return value;
  return new HalError('HARDWARE_ERROR', errorMessage(value), { cause: value });
}

/**
 * The error of a call to a fleet device that is offline: NOT_CONNECTED with details
 * `{ device, offline: true }` (plus anything in `extra`), the same whether the call went through
 * the device manager or straight through NATS, so a program tells "offline" apart from other
 * link failures by the details, not the message.
 */
export function deviceOfflineError(
  device: string,
  reason?: string,
  extra: HalErrorDetails = {},
  cause?: unknown,
): HalError {
  const message = `device "${device}" is offline${reason === undefined ? '' : `: ${reason}`}`;
  return new HalError('NOT_CONNECTED', message, {
    details: { ...extra, device, offline: true },
    ...(cause === undefined ? {} : { cause }),
  });
}
