export {
  HAL_ERROR_CODES,
  HalError,
  HalErrorCodeSchema,
  deviceOfflineError,
  errorMessage,
  isHalError,
  toHalError,
} from './errors.js';
export type { HalErrorCode, HalErrorDetails, HalErrorOptions } from './errors.js';

export { HALModeSchema } from './mode.js';
export type { HALMode } from './mode.js';

export { HALToolResultSchema, failureResult, successResult } from './result.js';
export type { HALToolResult } from './result.js';

export {
  CONNECTION_TYPES,
  ConnectionConfigSchema,
  HALConfigSchema,
  RobotConfigSchema,
  V1_ROBOT,
  maxLinearSpeedMPerS,
  minLinearSpeedMPerS,
  robotConfig,
  stepsPerCm,
} from './robot-config.js';
export type { ConnectionConfig, HALConfig, RobotConfig } from './robot-config.js';
export { ROBOT_SETTINGS, settingRangeText } from './robot-settings.js';
export type { RobotSetting, RobotSettingKey, SettingCommand } from './robot-settings.js';

export { CameraModelSchema, V1_CAMERA, cameraModel } from './camera-model.js';
export type { CameraModel } from './camera-model.js';

export {
  DetectedObjectSchema,
  DeviceInfoSchema,
  DistanceSensorsSchema,
  IMUReadingSchema,
  PoseSchema,
  SafetyStatusSchema,
  ScanResultSchema,
  ValueSourceSchema,
  Vector3Schema,
} from './pose.js';
export type {
  DeviceInfo,
  DistanceSensors,
  IMUReading,
  Pose,
  SafetyStatus,
  ScanResult,
  ValueSource,
  Vector3,
} from './pose.js';

export type {
  CommunicationInterface,
  HALLogLevel,
  HardwareAbstractionLayer,
  LocomotionInterface,
  ManipulationInterface,
  SafetyInterface,
  VisionInterface,
} from './interfaces.js';

export {
  DriveParamsSchema,
  EmergencyStopParamsSchema,
  MoveDistanceParamsSchema,
  MoveToParamsSchema,
  PlaySoundParamsSchema,
  RotateParamsSchema,
  SetLEDParamsSchema,
  SpeakParamsSchema,
  createCallSchemas,
} from './schemas/calls.js';
export type {
  CallName,
  CallParams,
  CallSchemas,
  DriveParams,
  EmergencyStopParams,
  MoveDistanceParams,
  MoveToParams,
  PlaySoundParams,
  RotateParams,
  SetLEDParams,
  SpeakParams,
} from './schemas/calls.js';

export { HAL_CALL_TABLE, findCall, motionCall } from './schemas/call-table.js';
export type {
  CallKind,
  CallLane,
  CallMotion,
  CallSpec,
  CallSubsystem,
  CallTable,
  CallToolSpec,
} from './schemas/call-table.js';
export {
  argsFromObject,
  callMethod,
  invokeCall,
  invokeSpec,
  objectFromArgs,
} from './schemas/invoke-call.js';
export { forwardCalls } from './schemas/forward-calls.js';
export type { ForwardedSubsystems } from './schemas/forward-calls.js';

export {
  FrameDataUrlSchema,
  LOG_LEVELS,
  LineSensorsSchema,
  LogParamsSchema,
  NoParamsSchema,
  READ_RESULT_SCHEMAS,
  SCAN_MODES,
  ScanParamsSchema,
} from './schemas/reads.js';
export type { LogParams, NoParams, ReadCallName, ScanParams } from './schemas/reads.js';

export { HalBoundary } from './validation.js';
export { ESTOP_REASON_MAX_BYTES, sanitizeEstopReason } from './estop-reason.js';
export type { HalBoundaryOptions } from './validation.js';

export { CAPABILITIES, hasCapability, parseCapability } from './capabilities.js';
export type { Capability } from './capabilities.js';

export {
  DEVICE_SUBJECT_TOKEN,
  EnvelopeSchema,
  HAL_MAJOR,
  HAL_MINOR,
  HalErrorPayloadSchema,
  buildSubject,
  envelopeTimeMs,
  makeEnvelope,
  parseEnvelope,
  parseSubject,
} from './envelope.js';
export type { Envelope, HalErrorPayload, SubjectParts } from './envelope.js';

// The shared vocabulary: one angle wrap and one planar pose for every package.
export { angleDifference, normalizeAngle } from './vocabulary/angle.js';
export type { PlanarPose } from './vocabulary/planar-pose.js';
export { TypedEmitter } from './vocabulary/typed-emitter.js';
export { EstopLatch } from './vocabulary/estop-latch.js';
export type { SerialLinkStats, TransportStats } from './link-stats.js';
export type { ListenerErrorHandler } from './vocabulary/typed-emitter.js';
export { scoped, silentLogger } from './vocabulary/logger.js';
export { nextTurn } from './vocabulary/next-turn.js';
export {
  backoffMs,
  deadline,
  delay,
  raceTimer,
  realTimers,
  timeoutError,
  withTimeout,
} from './vocabulary/time.js';
export type { RetryPolicy, Timers } from './vocabulary/time.js';
export type { LogLevel, Logger, ScopedLogger } from './vocabulary/logger.js';

export type {
  DriveDone,
  EmergencyStopDone,
  LedSetting,
  LitLed,
  MotionCommand,
  MotionDone,
  RobotPart,
  RobotPort,
  RobotSpeaker,
} from './robot-port.js';
export { lastTripError, ROBOT_PART_CAPABILITY } from './robot-port.js';
