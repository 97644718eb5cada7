import type { RobotConfig } from '@hal/types';
import type { SafetyLaneTiming } from '../safety-lane.js';
import type { RequestOptions } from '../transport/transport.js';
import { PHYSICAL_HAL_DEFAULTS as DEFAULTS } from './options.js';
import type { PhysicalHALOptions } from './options.js';

/**
 * When the HAL speaks to the robot, in real milliseconds: from its options, the robot's clock rate
 * (`timeScale`) and the robot's host timeout, read on every call because a reconnection may
 * report a new one.
 */
export class LinkTiming {
  readonly #options: PhysicalHALOptions;
  readonly #timeScale: number;
  readonly #robot: () => RobotConfig;
  /** The last request timing, and the host timeout it was worked out for. */
  #request: Readonly<RequestOptions> | undefined;
  #requestFor: number | undefined;

  constructor(options: PhysicalHALOptions, timeScale: number, robot: () => RobotConfig) {
    this.#options = options;
    this.#timeScale = timeScale;
    this.#robot = robot;
  }

  /** Real milliseconds for a span of robot time. */
  real(robotMs: number): number {
    return robotMs / this.#timeScale;
  }

  /**
   * Resend an unanswered request after a quarter of the host timeout (500 ms by default, never
   * more than the protocol's 2000 ms), so one lost packet cannot let the host timeout stop a
   * move; give it up once the protocol's 3 x 2000 ms have been spent.
   */
  request(): RequestOptions {
    // asked for on every request: the same object while the robot's host timeout is the same
    const hostTimeoutMs = this.#robot().hostTimeoutMs;
    if (this.#requestFor !== hostTimeoutMs || this.#request === undefined) {
      this.#request = Object.freeze(this.#requestOptions());
      this.#requestFor = hostTimeoutMs;
    }
    return this.#request;
  }

  #requestOptions(): RequestOptions {
    const timeoutMs =
      this.#options.requestTimeoutMs ??
      Math.max(
        DEFAULTS.minRequestTimeoutMs,
        Math.min(DEFAULTS.replyTimeoutMs, this.real(this.#robot().hostTimeoutMs / 4)),
      );
    const attempts =
      this.#options.attempts ??
      Math.max(
        DEFAULTS.attempts,
        Math.ceil((DEFAULTS.replyTimeoutMs * DEFAULTS.attempts) / timeoutMs),
      );
    return { timeoutMs, attempts };
  }

  /** The heartbeat period: a quarter of the host timeout, at most 500 robot ms. */
  heartbeatMs(): number {
    return Math.max(
      5,
      this.real(
        this.#options.heartbeatIntervalMs ??
          Math.min(DEFAULTS.heartbeatMaxMs, this.#robot().hostTimeoutMs / 4),
      ),
    );
  }

  /** The `get_status` period while a motion runs. */
  pollMs(): number {
    return Math.max(2, this.real(this.#options.pollIntervalMs ?? DEFAULTS.pollIntervalMs));
  }

  /** Slack beyond 1.2 x the planned duration before a motion is declared TIMEOUT. */
  motionMarginMs(): number {
    return this.#options.motionTimeoutMarginMs ?? DEFAULTS.motionTimeoutMarginMs;
  }

  /**
   * How `stop` and `estop` are resent: every 20 ms, within the same total budget as any other
   * request but never longer than the robot's host timeout: a robot that hears nothing from the
   * host for that long stops by itself, so a longer wait only delays the news that it could not be
   * told. Once the link is known `dead` (lost, or the robot silent for its host timeout) one short
   * try is all there is.
   */
  stopLane(dead: boolean): SafetyLaneTiming {
    if (this.#options.safetyLane !== undefined) return this.#options.safetyLane;
    const { timeoutMs, attempts } = this.request();
    const requestMs =
      timeoutMs === undefined || attempts === undefined
        ? DEFAULTS.safetyLane.totalMs
        : timeoutMs * attempts;
    const hostTimeoutMs = this.real(this.#robot().hostTimeoutMs);
    const totalMs = Math.min(
      requestMs,
      dead ? DEFAULTS.deadLinkStopMs : Math.max(hostTimeoutMs, 100),
    );
    return { resendMs: DEFAULTS.safetyLane.resendMs, totalMs };
  }
}
