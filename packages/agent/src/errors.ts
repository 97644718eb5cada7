import { errorMessage } from '@hal/types';

/** Why an agent run failed (see {@link AgentError}). */
export type AgentErrorCode =
  /** An option is missing or wrong (no model, bad URL, a cap that is not a positive number). */
  | 'CONFIG'
  /** The endpoint answered with an HTTP error (the status is in `details`). */
  | 'HTTP'
  /** The endpoint could not be reached. */
  | 'NETWORK'
  /** The endpoint gave no answer within the request timeout. */
  | 'TIMEOUT'
  /** The endpoint answered with something that is not a chat completion. */
  | 'BAD_REPLY'
  /** A chat provider other than the endpoint's client failed; its own error is the `cause`. */
  | 'PROVIDER';

/** The error class of the agent package: a literal `code`, `details`, and a `cause`. */
export class AgentError extends Error {
  override readonly name = 'AgentError';
  readonly code: AgentErrorCode;
  readonly details: Record<string, unknown> | undefined;

  constructor(
    code: AgentErrorCode,
    message: string,
    options: { details?: Record<string, unknown>; cause?: unknown } = {},
  ) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.details = options.details;
  }
}

/**
 * The message of `error` with the causes under it, e.g. `fetch failed (ECONNREFUSED: connect
 * ECONNREFUSED 127.0.0.1:1)`: fetch's own "fetch failed" says nothing without its cause.
 */
export function errorWithCauses(error: unknown): string {
  const parts: string[] = [];
  const seen = new Set<unknown>();
  for (let at: unknown = error; at !== undefined && at !== null && !seen.has(at);) {
    seen.add(at);
    const code = (at as { code?: unknown }).code;
    const message = errorMessage(at);
    const text =
      typeof code === 'string' && !message.includes(code) ? `${code}: ${message}` : message;
    if (text !== '' && !parts.includes(text)) parts.push(text);
    const inner = at instanceof AggregateError ? at.errors[0] : (at as { cause?: unknown }).cause;
    at = inner;
  }
  const [first, ...rest] = parts;
  return rest.length === 0 ? (first ?? String(error)) : `${first} (${rest.join('; ')})`;
}
