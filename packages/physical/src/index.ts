export { PhysicalHAL } from './hal/physical-hal.js';
export type { PhysicalHALOptions, RobotIdentity } from './hal/options.js';
export { calibrationParams } from './hal/calibration.js';
export type { CalibrationSource, WheelCalibration } from './hal/calibration.js';
export {
  calibrationDir,
  calibrationOf,
  calibrationPath,
  CalibrationFileSchema,
  canNameFile,
  readCalibrationFile,
  writeCalibrationFile,
} from './calibration/calibration-file.js';
export type { CalibrationFile } from './calibration/calibration-file.js';
export {
  calibratedGeometry,
  calibrationFileOf,
  calibrationSource,
} from './calibration/calibration-source.js';
export { DEVICE_SETTING_RANGES } from './protocol/device-config.js';
export type { SettingRange } from './protocol/device-config.js';

export { DEFAULT_SAFETY_LANE } from './safety-lane.js';
export type { SafetyLaneTiming } from './safety-lane.js';
export type { SessionState } from './session.js';

export { MockRobot } from './mock/mock-robot.js';
export type { MockRobotOptions } from './mock/mock-robot.js';
export type { MockTransportOptions } from './mock/mock-transport.js';

export { DEFAULT_ATTEMPTS, DEFAULT_REPLY_TIMEOUT_MS, ReplyMatcher } from './transport/transport.js';
export type {
  RequestOptions,
  SerialLinkStats,
  Transport,
  TransportContext,
  TransportFactory,
  TransportStats,
} from './transport/transport.js';
export { DEFAULT_UDP_PORT, udpTransport } from './transport/udp.js';
export type { UdpTransport, UdpTransportOptions } from './transport/udp.js';
export { openSerialPort, PARTIAL_FRAME_TIMEOUT_MS, serialTransport } from './transport/serial.js';
export type {
  SerialPortLike,
  SerialPortOpener,
  SerialTransport,
  SerialTransportOptions,
} from './transport/serial.js';

export { MAX_MESSAGE_BYTES, MessageCodec } from './protocol/codec.js';
export type { DecodeResult, WireReply } from './protocol/codec.js';
export { createAuthenticator, MAC_SUFFIX_LENGTH } from './protocol/auth.js';
export type { MessageAuthenticator } from './protocol/auth.js';
export {
  AuthSchemeSchema,
  DeviceConfigSchema,
  EstopReplySchema,
  HeartbeatReplySchema,
  HelloReplySchema,
  LedStateSchema,
  MOVE_OUTCOMES,
  MotionReplySchema,
  REPLY_SCHEMAS,
  ReplyEnvelopeSchema,
  ResetEstopReplySchema,
  SafetyStateSchema,
  SetConfigReplySchema,
  SetLedReplySchema,
  StatusReplySchema,
  StopReplySchema,
  StopReportSchema,
} from './protocol/schemas.js';
export type {
  AuthScheme,
  Command,
  DeviceConfig,
  EstopReply,
  HeartbeatReply,
  HelloReply,
  LedState,
  MotionReply,
  MoveOutcome,
  ReplyEnvelope,
  ReplyOf,
  RequestParams,
  ResetEstopReply,
  SafetyState,
  SetConfigReply,
  SetLedReply,
  StatusReply,
  StopReply,
  StopReport,
} from './protocol/schemas.js';

export { crc16, decodeFrame, encodeFrame, MAX_PAYLOAD_BYTES } from './serial/frame.js';
export type { Frame, FrameError, FrameType } from './serial/frame.js';
export { FrameDecoder } from './serial/frame-decoder.js';
export type { FrameHandlers } from './serial/frame-decoder.js';

export { MjpegCamera } from './camera/mjpeg.js';
export type { MjpegCameraOptions, MjpegStats } from './camera/mjpeg.js';
export { boundaryOf, MultipartParser } from './camera/multipart.js';
