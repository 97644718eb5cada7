/** Why a navigation operation failed (see {@link NavigationError}). */
export type NavigationErrorCode =
  /** Configuration is missing or wrong (no model name, bad URL, bad option). */
  | 'CONFIG'
  /** A decision provider could not produce a decision (HTTP error, no valid reply). */
  | 'PROVIDER_ERROR'
  /** A decision did not match the decision schema. */
  | 'INVALID_DECISION'
  /** A wait ran out. */
  | 'TIMEOUT'
  /** The operation was cancelled through its AbortSignal. */
  | 'ABORTED';

/** The error class of the navigation package: a literal `code`, `details`, and a `cause`. */
export class NavigationError extends Error {
  override readonly name = 'NavigationError';
  readonly code: NavigationErrorCode;
  readonly details: Record<string, unknown> | undefined;

  constructor(
    code: NavigationErrorCode,
    message: string,
    options: { details?: Record<string, unknown>; cause?: unknown } = {},
  ) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.details = options.details;
  }
}

/** `value` when it is a positive number (an integer when `integer`), else a CONFIG error naming it. */
export function positiveOption(name: string, value: number, integer = false): number {
  if (!Number.isFinite(value) || value <= 0 || (integer && !Number.isInteger(value))) {
    throw new NavigationError(
      'CONFIG',
      `"${name}" must be a positive ${integer ? 'integer' : 'number'}, got ${value}`,
    );
  }
  return value;
}
