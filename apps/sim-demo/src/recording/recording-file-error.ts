import type { RecordingReadErrorCode } from '@hal/recorder';

/**
 * Why a file cannot be played back: the recorder's reader refused it (not MCAP, empty, no header,
 * damaged with nothing readable), or it has none of the robot's topics.
 */
export type RecordingFileErrorCode = RecordingReadErrorCode | 'NO_ROBOT_TOPICS';

/** A file the demo refuses to play back, and why. */
export class RecordingFileError extends Error {
  override readonly name = 'RecordingFileError';
  readonly code: RecordingFileErrorCode;

  constructor(code: RecordingFileErrorCode, message: string) {
    super(message);
    this.code = code;
  }
}
