import type { WebSocket } from 'ws';
import type { Role } from '../protocol.js';

/** One connected, authenticated client. */
export interface ClientSession {
  id: string;
  socket: WebSocket;
  role: Role;
  /** When its last message arrived, ms (Date.now). */
  lastSeen: number;
  subscribed: boolean;
  /** Its motion calls still running. */
  running: number;
}
