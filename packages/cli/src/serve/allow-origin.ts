// `hal serve --allow-origin <origin>`: a web page's origin the WebSocket door trusts beyond this
// machine's own (repeatable). The origin is checked as serveHal checks its allowedOrigins.
import { trustedOrigin } from '@hal/runtime';
import { isHalError } from '@hal/types';
import { usageError } from '../values.js';

/** Adds one `--allow-origin` value, normalised, to the ones given before it. */
export function allowOriginArg(value: string, previous: string[] | undefined): string[] {
  try {
    return [...(previous ?? []), trustedOrigin(value)];
  } catch (error) {
    if (!isHalError(error)) throw error;
    throw usageError(
      `"--allow-origin" must be an origin as a browser sends it, http(s)://HOST[:PORT], got "${value}"`,
    );
  }
}
