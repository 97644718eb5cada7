import type { Logger } from '@hal/types';
import type { MessageCodec } from './protocol/codec.js';
import type { Command, HelloReply } from './protocol/schemas.js';
import type { SafetyLaneTiming } from './safety-lane.js';
import type { RequestOptions, Transport } from './transport/transport.js';

/** Where a session is. */
export type SessionState = 'idle' | 'connected' | 'lost' | 'closed';

/** Options of a {@link Session}. */
export interface SessionOptions {
  transport: Transport;
  codec: MessageCodec;
  logger: Logger;
  /** Names the host software in `hello`. */
  client?: string;
  /** Heartbeat period, real ms (asked each time, as the robot's host timeout may change). */
  heartbeatIntervalMs: () => number;
  /** While the link is lost, try `hello` again this often, ms. */
  reconnectIntervalMs: number;
  /** Per-request timeout and attempts (asked before every request). */
  request?: () => RequestOptions;
  /** Called after every successful (re)connection, outside the request queue. */
  onConnected?: (hello: HelloReply, reconnect: boolean) => void | Promise<void>;
  /** Called with every successful reply's data. */
  onReply?: (cmd: Command, data: Record<string, unknown>) => void;
  /** Called with whatever a {@link Session.command} rejects with, before it rejects. */
  onCommandFailed?: (error: unknown) => void;
  /** Called when the state changes. */
  onStateChange?: (state: SessionState, reason: string) => void;
  /** Timing of the safety lane (asked before every stop); default {@link DEFAULT_SAFETY_LANE}. */
  safetyLane?: () => SafetyLaneTiming;
}
