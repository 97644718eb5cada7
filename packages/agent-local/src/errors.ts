/** Why the local provider failed (see {@link LocalModelError}). */
export type LocalModelErrorCode =
  /** The GGUF file is not there. */
  | 'MODEL_MISSING'
  /** The file is there but is not a GGUF model llama.cpp can load (corrupt, truncated, other). */
  | 'MODEL_INVALID'
  /** A tool's JSON Schema uses something the grammar cannot express; the message names the tool. */
  | 'SCHEMA_UNSUPPORTED'
  /**
   * node-llama-cpp, the optional peer dependency that runs the model, is not installed; the
   * message says what to install.
   */
  | 'DEPENDENCY_MISSING'
  /** The model could not be fetched: the package index or the wheel could not be read. */
  | 'FETCH_FAILED'
  /** What was fetched is not the pinned model file (its sha256 differs): nothing was written. */
  | 'CHECKSUM'
  /** An option is wrong (threads, context size, token limits). */
  | 'CONFIG'
  /** The model failed while generating, or its output could not be read. */
  | 'GENERATION';

/** The error class of this package: a literal `code`, `details`, and a `cause`. */
export class LocalModelError extends Error {
  override readonly name = 'LocalModelError';
  readonly code: LocalModelErrorCode;
  readonly details: Record<string, unknown> | undefined;

  constructor(
    code: LocalModelErrorCode,
    message: string,
    options: { details?: Record<string, unknown>; cause?: unknown } = {},
  ) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.details = options.details;
  }
}
