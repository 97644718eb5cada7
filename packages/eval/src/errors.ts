/** What went wrong in an evaluation. */
export type EvalErrorCode =
  /** A task file could not be read, broke the schema, or names something its world lacks. */
  | 'TASK_INVALID'
  /** The options of a run are wrong (an unknown group, agent, or a bad number). */
  | 'CONFIG'
  /** A robot the tasks were to run on could not be reached or failed during a trial. */
  | 'ROBOT';

/** An error of `@hal/eval`, with a literal code; task errors name the file and the field. */
export class EvalError extends Error {
  override readonly name = 'EvalError';
  readonly code: EvalErrorCode;
  /** For TASK_INVALID: the file and the field (`tasks.3.checks.0.object`). */
  readonly file: string | undefined;
  readonly field: string | undefined;

  constructor(
    code: EvalErrorCode,
    message: string,
    options: { file?: string; field?: string; cause?: unknown } = {},
  ) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.file = options.file;
    this.field = options.field;
  }
}
