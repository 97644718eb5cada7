// @hal/physical/protocol: the robot's wire protocol 1.1 piece by piece, for tools that speak it
// without PhysicalHAL (a bench, a protocol checker, another host): the JSON codec and its reply
// schemas, HMAC authentication, the CRC-16 serial frames, request/reply matching with retries,
// and the camera's multipart MJPEG parser.
export { MessageCodec } from './codec.js';
export type { DecodeResult, WireReply } from './codec.js';
export { createAuthenticator } from './auth.js';
export type { MessageAuthenticator } from './auth.js';
export {
  DeviceConfigSchema,
  REPLY_SCHEMAS,
  ReplyEnvelopeSchema,
  StatusReplySchema,
} from './schemas.js';
export type { AuthScheme, DeviceConfig, ReplyEnvelope, StatusReply } from './schemas.js';

export { crc16, decodeFrame, encodeFrame } from '../serial/frame.js';
export type { Frame, FrameError, FrameType } from '../serial/frame.js';
export { FrameDecoder } from '../serial/frame-decoder.js';
export type { FrameHandlers } from '../serial/frame-decoder.js';

export { ReplyMatcher } from '../transport/transport.js';
export { openSerialPort } from '../transport/serial.js';
export { MultipartParser } from '../camera/multipart.js';
