// @hal/physical/protocol: the robot's wire protocol 1.1 piece by piece, for tools that speak it
// without PhysicalHAL (a bench, a protocol checker, another host): the JSON codec and its reply
// schemas, HMAC authentication, the CRC-16 serial frames, request/reply matching with retries,
// and the camera's multipart MJPEG parser.
export { MAX_MESSAGE_BYTES, MessageCodec } from './codec.js';
export type { DecodeResult, WireReply } from './codec.js';
export { createAuthenticator, MAC_SUFFIX_LENGTH } from './auth.js';
export type { MessageAuthenticator } from './auth.js';
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
} from './schemas.js';
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
} from './schemas.js';

export { crc16, decodeFrame, encodeFrame, MAX_PAYLOAD_BYTES } from '../serial/frame.js';
export type { Frame, FrameError, FrameType } from '../serial/frame.js';
export { FrameDecoder } from '../serial/frame-decoder.js';
export type { FrameHandlers } from '../serial/frame-decoder.js';

export {
  DEFAULT_ATTEMPTS,
  DEFAULT_REPLY_TIMEOUT_MS,
  ReplyMatcher,
} from '../transport/transport.js';
export { openSerialPort, PARTIAL_FRAME_TIMEOUT_MS } from '../transport/serial.js';
export { boundaryOf, MultipartParser } from '../camera/multipart.js';
