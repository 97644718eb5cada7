export { McapRecorder } from './recorder.js';
export type { RecorderOptions, RecorderStats } from './recorder-options.js';
export { recordHal, RECORDER_VERSION } from './record-hal.js';
export type { RecordHalOptions } from './record-hal-options.js';
export { memorySink } from './file-sink.js';
export type { RecordingSink } from './file-sink.js';
export { readRecording, readRecordingFile } from './read-recording.js';
export type { ReadRecordingOptions, Recording } from './read-recording.js';
export type { RecordedChannel, RecordedMessage } from './recording-builder.js';
export type { RecordingGap } from './recover-records.js';
export { RecordingReadError } from './recording-read-error.js';
export type { RecordingReadErrorCode } from './recording-read-error.js';
export type { ChunkCompression } from './compression.js';
export {
  AGENT_EVENT,
  CALL_RECORD,
  HAL_POSE,
  HalCallRecordSchema,
  LINK_STATS,
  LinkStatsSchema,
  RecorderLossSchema,
  SAFETY_EVENT,
  SafetyEventSchema,
  TOPICS,
  WHEEL_STEPS,
  WheelStepsSchema,
} from './messages.js';
export type {
  HalCallRecord,
  LinkStats,
  RecorderLoss,
  SafetyEvent,
  WheelSteps,
} from './messages.js';
export { linkTelemetry } from './link-telemetry.js';
export type { LinkTelemetry } from './link-telemetry.js';
export { robotNamespace } from './namespace.js';
export type { RobotNamespace, RobotTopics } from './namespace.js';
export {
  COMPRESSED_IMAGE,
  FRAME_TRANSFORM,
  LOG,
  POSE_IN_FRAME,
  quaternionFromEuler,
} from './foxglove-schemas.js';
export type { NamedJsonSchema } from './foxglove-schemas.js';
export { PERCEPTION_TOPICS, recordPerception } from './record-perception.js';
export type {
  PerceivedLook,
  PerceptionRecording,
  RecordablePerception,
  RecordPerceptionOptions,
} from './record-perception.js';
export { OCCUPANCY } from './perception-messages.js';
export type { PerceivedGrid, PerceivedObject, PerceivedSighting } from './perception-messages.js';
export { summarizeRecording } from './summary.js';
export type { RecordingSummary, RobotSummary } from './summary.js';
export { replayRecording } from './replay.js';
export type { ReplayedCall, ReplayReport } from './replay.js';
export { trajectorySvg } from './trajectory-svg.js';
