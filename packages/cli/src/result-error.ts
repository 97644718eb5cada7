// A failed HAL result as the HAL's own error, so its code passes through to the exit.
import { HalError } from '@hal/types';
import type { HALToolResult } from '@hal/types';

export function resultError(result: HALToolResult): HalError {
  return new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? 'the call failed', {
    ...(result.details === undefined ? {} : { details: result.details }),
  });
}
