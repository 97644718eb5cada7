import type { CallTable, Logger, RobotConfig } from '@hal/types';
import type { NatsConnectionSource } from './connection.js';

/** How `serveHalOnNats` serves a HAL. */
export type GatewayOptions = NatsConnectionSource & {
  /** The device id used in `hal.v1.dev.{deviceId}...` subjects and as the envelope's sender. */
  deviceId: string;
  /**
   * Whether this gateway also answers the spec's bare subjects (`hal.v1.motor.differential.cmd`)
   * and streams on them: the device a spec-only client talks to. Default true; in a fleet exactly
   * one device (or none) is the default.
   */
  defaultDevice?: boolean;
  /** State stream rate, Hz (10..100; 0 turns the streams off). Default 20. */
  stateRateHz?: number;
  /**
   * An open-ended drive (no duration) is stopped when its controller has sent nothing (command or
   * heartbeat) for this long, ms. Default 3000.
   */
  controllerTimeoutMs?: number;
  /** How often the capability announcement is repeated, ms. Default 5000. */
  announceIntervalMs?: number;
  /** Geometry and limits for mapping body velocities onto wheels. Default the V1 robot. */
  robot?: RobotConfig;
  logger?: Logger;
  /** The calls served on `hal.call.req`; default the HAL's own call table. */
  calls?: CallTable;
};
