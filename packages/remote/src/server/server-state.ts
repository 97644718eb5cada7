import type { ControllerWatch, ServedCalls } from '@hal/runtime';
import type { HardwareAbstractionLayer, LogLevel } from '@hal/types';
import type { WebSocket } from 'ws';
import type { ClientSession } from './client-session.js';
import type { ServeSettings } from './serve-settings.js';
import type { SessionOutput } from './session-output.js';

/** Logs one line of the server at `level`. */
export type ServerLog = (
  level: LogLevel,
  message: string,
  fields?: Record<string, unknown>,
) => void;

/** What the parts of one server share: its HAL, its clients, who controls, and how to answer. */
export interface ServerState {
  readonly hal: HardwareAbstractionLayer;
  readonly settings: ServeSettings;
  /** The id the server goes by, when not the HAL's own. */
  readonly deviceId: string | undefined;
  readonly served: ServedCalls;
  readonly sessions: Map<WebSocket, ClientSession>;
  /** The client in control, if any. */
  controller: ClientSession | undefined;
  readonly controllers: ControllerWatch;
  readonly out: SessionOutput;
  readonly log: ServerLog;
  /** Forgets a client that left (or is dropped), and stops the robot if it was the controller. */
  release(session: ClientSession, why: string): void;
}
