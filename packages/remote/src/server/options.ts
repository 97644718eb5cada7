import type { CallTable, Logger } from '@hal/types';

/** How {@link serveHal} serves a HAL. */
export interface ServeHalOptions {
  /** Address to bind. Default 127.0.0.1; any non-loopback address needs `token`. */
  host?: string;
  /** TCP port; 0 picks a free one. Default 8765. */
  port?: number;
  /** Shared secret (at least 16 characters) clients present as a Bearer token or `?token=`. */
  token?: string;
  /**
   * Web pages trusted beyond this machine's own, as the origins browsers send
   * (`https://robot.example`, `http://192.168.1.20:5173`). Without a token, a connection whose
   * `Origin` is neither loopback nor one of these (a page on another site) is refused with HTTP
   * 403, as is one whose `Host` is not a loopback name (DNS rebinding). Clients that send no
   * `Origin` (programs) are not affected; with a token, every client presents it instead.
   */
  allowedOrigins?: readonly string[];
  /** State messages per second to each subscriber. Default 10. */
  stateRateHz?: number;
  /**
   * A client silent this long (no message, no heartbeat) is dropped; if it controlled the robot,
   * its motion is stopped. Default 2000 ms (500..10000).
   */
  heartbeatTimeoutMs?: number;
  /** Bigger messages get a MALFORMED error reply (the connection stays). Default 64 KiB. */
  maxMessageBytes?: number;
  /**
   * The device's id: the `device_id` of the server's messages, and the id its hello gives the
   * device (a client's `getDeviceInfo().id`). Default the served HAL's device id.
   */
  deviceId?: string;
  logger?: Logger;
  /** The calls served; default the HAL's own call table. */
  calls?: CallTable;
}

export const SERVE_DEFAULTS = {
  host: '127.0.0.1',
  port: 8765,
  stateRateHz: 10,
  heartbeatTimeoutMs: 2000,
  maxMessageBytes: 64 * 1024,
} as const;

/** What {@link serveHal} returns. */
export interface HalServer {
  /** Where it listens, e.g. `ws://127.0.0.1:8765`. */
  readonly url: string;
  readonly address: { host: string; port: number };
  /** How many clients are connected. */
  clientCount(): number;
  /** Disconnects every client and stops listening. The HAL is left to its owner (not cleaned up). */
  close(): Promise<void>;
}
