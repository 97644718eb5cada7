import { AgentError } from '@hal/agent';
import { HalError, errorMessage } from '@hal/types';
import type { HalErrorCode } from '@hal/types';

/** Which way a vision model failed, as `details.failure` of the HalError. */
export type VlmFailure = 'timeout' | 'network' | 'http' | 'reply';

/** Where the failure happened, for the error's message and details. */
export interface VlmFailureContext {
  detector: string;
  url: string;
  timeoutMs: number;
  /** Whether the detection's own deadline ran out. */
  timedOut: boolean;
}

/**
 * The HalError of a failed request to a vision model: `TIMEOUT` (no answer within the time
 * allowed), `NOT_CONNECTED` (unreachable), `AUTH_FAILED` (HTTP 401/403), `HARDWARE_ERROR` (any
 * other HTTP error; `details.status`), `MALFORMED` (a reply with no readable list of objects).
 * The message names the detector, the endpoint and the cause; `details.failure` says which way
 * it failed.
 */
export function vlmFailure(error: unknown, context: VlmFailureContext): HalError {
  const { detector, url, timeoutMs } = context;
  const make = (
    code: HalErrorCode,
    failure: VlmFailure,
    what: string,
    extra: Record<string, unknown> = {},
  ) =>
    new HalError(code, `${detector} at ${url}: ${what}`, {
      details: { detector, endpoint: url, failure, ...extra },
      cause: error,
    });
  if (context.timedOut || (error instanceof AgentError && error.code === 'TIMEOUT')) {
    return make('TIMEOUT', 'timeout', `no answer within ${timeoutMs} ms`, { timeoutMs });
  }
  if (!(error instanceof AgentError)) {
    const message = errorMessage(error);
    return make('HARDWARE_ERROR', 'network', `the request failed: ${message}`);
  }
  const status = error.details?.['status'];
  switch (error.code) {
    case 'NETWORK':
      return make(
        'NOT_CONNECTED',
        'network',
        `cannot reach the vision model: ${error.message.replace(`request to ${url} failed: `, '')}`,
      );
    case 'HTTP':
      return make(
        status === 401 || status === 403 ? 'AUTH_FAILED' : 'HARDWARE_ERROR',
        'http',
        `the vision model's server answered ${error.message.replace(` from ${url}`, '')}`,
        typeof status === 'number' ? { status } : {},
      );
    case 'BAD_REPLY':
      return make('MALFORMED', 'reply', `unreadable reply: ${error.message}`);
    default:
      return make('HARDWARE_ERROR', 'network', error.message);
  }
}
