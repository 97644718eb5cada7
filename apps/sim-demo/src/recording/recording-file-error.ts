/** Why a file cannot be played back. */
export type RecordingFileErrorCode = 'NOT_MCAP' | 'NO_ROBOT_TOPICS';

/** A file the demo refuses to play back, and why. */
export class RecordingFileError extends Error {
  override readonly name = 'RecordingFileError';
  readonly code: RecordingFileErrorCode;

  constructor(code: RecordingFileErrorCode, message: string) {
    super(message);
    this.code = code;
  }
}
