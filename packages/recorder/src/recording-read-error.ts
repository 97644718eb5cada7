/** Why a file was refused as a recording. */
export type RecordingReadErrorCode =
  /** The file has no bytes at all. */
  | 'EMPTY'
  /** The file does not start with MCAP's magic bytes: it is some other kind of file. */
  | 'NOT_MCAP'
  /** The file starts as MCAP but ends, or breaks, before its header record: nothing was recorded. */
  | 'NO_HEADER'
  /** The file is MCAP, but damaged so that not one message could be read from it. */
  | 'DAMAGED';

/**
 * A file that {@link readRecording} refuses: not MCAP, empty, or with nothing readable in it.
 * The message names the file (as the caller named it) and the reason, with the byte offset where
 * reading stopped when there is one.
 */
export class RecordingReadError extends Error {
  override readonly name = 'RecordingReadError';
  readonly code: RecordingReadErrorCode;
  /** Where in the file reading stopped (bytes from its start), when it stopped at a place. */
  readonly offset: number | undefined;

  constructor(
    code: RecordingReadErrorCode,
    message: string,
    options: { offset?: number; cause?: unknown } = {},
  ) {
    super(message, options.cause === undefined ? undefined : { cause: options.cause });
    this.code = code;
    this.offset = options.offset;
  }
}
