// For the CLI's unit tests: what the one usage error every option parser and check throws
// looks like (exit 2, its message naming the option or place).
import { expect } from 'vitest';

/** Matches the CLI's usage error whose message is `message` (or matches it). */
export function usageErrorLike(
  message: string | RegExp,
): ReturnType<typeof expect.objectContaining> {
  return expect.objectContaining({
    name: 'CliError',
    code: 'USAGE',
    exitCode: 2,
    message: typeof message === 'string' ? message : expect.stringMatching(message),
  });
}
