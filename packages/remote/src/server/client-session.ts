import type { WebSocket } from 'ws';
import type { Role } from '../protocol.js';

/** One connected, authenticated client. */
export interface ClientSession {
  id: string;
  socket: WebSocket;
  role: Role;
  subscribed: boolean;
  /** Its motion calls still running. */
  running: number;
}
