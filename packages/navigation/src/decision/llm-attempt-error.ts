/** Thrown inside one attempt at a decision: says whether another attempt may help. */
export class AttemptError extends Error {
  constructor(
    message: string,
    /** Whether asking again may give a valid decision. */
    readonly retryable: boolean,
    /** What to tell the model about its reply before asking again, when the reply was the problem. */
    readonly feedback?: string,
    /** How long the server asked to be left alone before the next attempt (Retry-After), ms. */
    readonly retryAfterMs?: number,
  ) {
    super(message);
  }
}
