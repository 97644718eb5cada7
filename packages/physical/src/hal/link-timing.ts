import type { RobotConfig } from '@hal/types';
import { DEFAULT_ATTEMPTS, DEFAULT_REPLY_TIMEOUT_MS } from '../transport/transport.js';
import type { RequestOptions } from '../transport/transport.js';
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
      Math.max(20, Math.min(DEFAULT_REPLY_TIMEOUT_MS, this.real(this.#robot().hostTimeoutMs / 4)));
    const attempts =
      this.#options.attempts ??
      Math.max(
        DEFAULT_ATTEMPTS,
        Math.ceil((DEFAULT_REPLY_TIMEOUT_MS * DEFAULT_ATTEMPTS) / timeoutMs),
      );
    return { timeoutMs, attempts };
  }

  /** The heartbeat period: a quarter of the host timeout, at most 500 robot ms. */
  heartbeatMs(): number {
    return Math.max(
      5,
      this.real(
        this.#options.heartbeatIntervalMs ?? Math.min(500, this.#robot().hostTimeoutMs / 4),
      ),
    );
  }

  /** The `get_status` period while a motion runs. */
  pollMs(): number {
    return Math.max(2, this.real(this.#options.pollIntervalMs ?? 100));
  }

  /** Slack beyond 1.2 x the planned duration before a motion is declared TIMEOUT. */
  motionMarginMs(): number {
    return this.#options.motionTimeoutMarginMs ?? 2000;
  }
}
