import type { CallTable, HALMode, Logger } from '@hal/types';
import type { WebSocketConstructor } from './websocket.js';

/** How a {@link RemoteHAL} reaches its server. */
export interface RemoteHALOptions {
  /** The server, e.g. `ws://127.0.0.1:8765`. */
  url: string;
  /** The server's token, when it has one (sent as a Bearer header with `ws`, else `?token=`). */
  token?: string;
  /**
   * 'auto' (default): control the robot if no one does, else watch; 'take': take control on
   * connecting (the previous controller is told); 'watch': never control (reads, state, e-stop; connects with `?role=watch`).
   */
  control?: 'auto' | 'take' | 'watch';
  /** WebSocket constructor. Default the `ws` package in Node, `globalThis.WebSocket` elsewhere. */
  WebSocket?: WebSocketConstructor;
  /** `device_id` of this client's messages. Default `remote-client`. */
  clientId?: string;
  /** Mode reported before the server has said its own. Default 'physical'. */
  mode?: HALMode;
  /** Waiting for the connection and the server's hello, ms. Default 5000. */
  connectTimeoutMs?: number;
  /** Waiting for the reply to a read or a non-motion call, ms. Default 10000. */
  requestTimeoutMs?: number;
  /** Waiting for the reply to a motion call, ms (the served HAL has its own). Default 120000. */
  motionTimeoutMs?: number;
  /** Reconnect when the server goes away (calls fail NOT_CONNECTED meanwhile). Default true. */
  reconnect?: boolean;
  /** First delay before reconnecting, ms; doubles up to 5000. Default 250. */
  reconnectDelayMs?: number;
  logger?: Logger;
  /** The calls this HAL forwards; default the HAL's own call table. */
  calls?: CallTable;
}

export const REMOTE_DEFAULTS = {
  control: 'auto',
  clientId: 'remote-client',
  mode: 'physical',
  connectTimeoutMs: 5000,
  requestTimeoutMs: 10_000,
  motionTimeoutMs: 120_000,
  reconnect: true,
  reconnectDelayMs: 250,
} as const;
