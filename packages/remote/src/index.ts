export { RemoteHAL } from './client/remote-hal.js';
export type { RemoteHALOptions } from './client/options.js';
export type { WebSocketConstructor, WebSocketLike } from './client/websocket.js';
export { decodeMessage, encodeArgs, encodeMessage } from './protocol.js';
export type { Message, MessageSchema, Role } from './protocol.js';
