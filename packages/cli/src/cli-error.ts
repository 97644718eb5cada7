// The failures of the command line itself (bad usage, nothing found, a check that failed), beside
// the HAL's own HalError codes, which commands pass through unchanged.

export const CLI_ERROR_CODES = ['USAGE', 'NOT_FOUND', 'CHECK_FAILED', 'FAILED'] as const;
export type CliErrorCode = (typeof CLI_ERROR_CODES)[number];

/** A failure the CLI reports as `hal: CODE: message` (or JSON) and exits non-zero. */
export class CliError extends Error {
  override readonly name = 'CliError';
  constructor(
    readonly code: CliErrorCode,
    message: string,
    /** The process exit code: 2 for usage errors, 1 otherwise. */
    readonly exitCode: number = code === 'USAGE' ? 2 : 1,
  ) {
    super(message);
  }
}
