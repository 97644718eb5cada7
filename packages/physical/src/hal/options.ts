import type { Logger } from '@hal/types';
import type { StartPose } from '../pose-tracker.js';
import type { CalibrationSource } from './calibration.js';
import type { AuthScheme, DeviceConfig } from '../protocol/schemas.js';
import { DEFAULT_SAFETY_LANE } from '../safety-lane.js';
import type { SafetyLaneTiming } from '../safety-lane.js';
import { DEFAULT_ATTEMPTS, DEFAULT_REPLY_TIMEOUT_MS } from '../transport/transport.js';
import type { TransportFactory } from '../transport/transport.js';

/**
 * Every default of a PhysicalHAL, in one place (the options below say how each is used). Robot ms
 * are scaled by `timeScale`; real ms are not.
 */
export const PHYSICAL_HAL_DEFAULTS = Object.freeze({
  /** The robot's clock runs at real time. */
  timeScale: 1,
  /** The longest heartbeat period, robot ms (else a quarter of the host timeout). */
  heartbeatMaxMs: 500,
  /** `get_status` polls while a motion runs, robot ms. */
  pollIntervalMs: 100,
  /** `hello` again while the link is lost, real ms. */
  reconnectIntervalMs: 1000,
  /** A motion's slack beyond 1.2 x its planned duration, real ms. */
  motionTimeoutMarginMs: 2000,
  /** The protocol's reply timeout, real ms, and the longest a request waits before a resend. */
  replyTimeoutMs: DEFAULT_REPLY_TIMEOUT_MS,
  /** The protocol's sends of a request (3 x 2000 ms is its whole budget). */
  attempts: DEFAULT_ATTEMPTS,
  /** The shortest resend period, real ms. */
  minRequestTimeoutMs: 20,
  /** How `stop` and `estop` are resent until acknowledged. */
  safetyLane: DEFAULT_SAFETY_LANE,
  /** How long a stop is resent once the link is known dead, real ms. */
  deadLinkStopMs: 300,
  /** How long `cleanup()` tries to stop the motors, real ms. */
  cleanupStopMs: 500,
  /** How the host names itself in `hello`. */
  client: '@hal/physical',
});

/** Options of {@link PhysicalHAL}, beside its {@link HALConfig}. */
export interface PhysicalHALOptions {
  /** The link to the robot; default built from `config.connection` (wifi: UDP, serial: serial). */
  transport?: TransportFactory;
  /** Where the HAL logs (namespaces `hal:physical:*`). Default: nowhere. */
  logger?: Logger;
  /** The clock results are stamped with, ms. Default `Date.now`. */
  now?: () => number;
  /**
   * How much faster than real time the robot's clock runs (1 for a real robot; the emulator's
   * `--time-scale`). Scales the heartbeat, polling and motion timeouts.
   */
  timeScale?: number;
  /** Heartbeat period, robot ms. Default a quarter of the robot's host timeout, at most 500. */
  heartbeatIntervalMs?: number;
  /** Period of `get_status` polls while a motion runs, robot ms. Default 100. */
  pollIntervalMs?: number;
  /** While the link is lost, say `hello` again this often, real ms. Default 1000. */
  reconnectIntervalMs?: number;
  /**
   * Resend an unanswered request after this long, real ms. Default a quarter of the robot's host
   * timeout (500 ms), scaled by `timeScale`, so that one lost datagram can never let the host
   * timeout fire; resending the same bytes keeps every request exactly-once.
   */
  requestTimeoutMs?: number;
  /**
   * Give a request up after this many sends. Default: as many as fit in the protocol's
   * 3 x 2000 ms budget.
   */
  attempts?: number;
  /**
   * How `stop()` and `emergencyStop()` are resent until the robot acknowledges them, real ms.
   * Default every 20 ms, for as long as any other request is retried (`requestTimeoutMs` x
   * `attempts`: 6000 ms by default).
   */
  safetyLane?: SafetyLaneTiming;
  /**
   * How long `initialize()` says `hello` before it gives up, real ms (resent every
   * `requestTimeoutMs`). Default one request's budget, `requestTimeoutMs` x `attempts` (6000 ms).
   */
  connectTimeoutMs?: number;
  /** Extra time a motion may take beyond its planned duration, real ms. Default 2000. */
  motionTimeoutMarginMs?: number;
  /** Names the host software in `hello`. */
  client?: string;
  /**
   * The robot's measured wheel geometry, looked up by the device id its `hello` reports and sent
   * with `set_config` after every hello (the first and each reconnect). Default: none (the
   * robot's own geometry).
   */
  calibration?: CalibrationSource;
  /**
   * Where the robot stands when `initialize()` connects, in the frame its poses are to be given
   * in (a room's, a map's): metres and radians. Default the origin, facing +x. The robot cannot
   * tell where it is; this is the caller's word for it, and odometry goes on from there.
   */
  startPose?: StartPose;
}

/** What the robot said about itself when the session opened. */
export interface RobotIdentity {
  deviceId: string;
  firmwareVersion: string;
  protocolVersion: string;
  /** Whether messages are MACed with a pre-shared key (`authScheme` is `hmac-sha256`). */
  auth: boolean;
  /**
   * How the robot authenticates: `hmac-sha256`, or `none` when it was built with the
   * unauthenticated opt-out (anyone who reaches it can command it).
   */
  authScheme: AuthScheme;
  capabilities: string[];
  config: DeviceConfig;
}
