export { RemoteHAL } from './client/remote-hal.js';
export { REMOTE_DEFAULTS } from './client/options.js';
export type { RemoteHALOptions } from './client/options.js';
export type { WebSocketConstructor, WebSocketLike } from './client/websocket.js';
export {
  CONTROLLER_CALLS,
  MESSAGE_SCHEMAS,
  REMOTE_CALLS,
  RESULT_CALLS,
  VALUE_CALLS,
  decodeArgs,
  decodeMessage,
  encodeArgs,
  encodeMessage,
} from './protocol.js';
export type {
  CallPayload,
  ControlPayload,
  HelloPayload,
  Message,
  MessageSchema,
  RemoteCallName,
  ReplyPayload,
  ResultCallName,
  Role,
  StatePayload,
  ValueCallName,
} from './protocol.js';
