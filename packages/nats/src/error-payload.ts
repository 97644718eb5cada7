import { isHalError, toHalError } from '@hal/types';
import type { HalErrorPayload } from '@hal/types';

/** The spec's error shape for anything thrown. */
export function errorPayload(thrown: unknown): HalErrorPayload {
  const error = isHalError(thrown) ? thrown : toHalError(thrown);
  const payload: HalErrorPayload = { code: error.code, message: error.message };
  if (error.details !== undefined) payload.details = error.details;
  return payload;
}
