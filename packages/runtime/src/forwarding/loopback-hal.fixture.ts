// A ForwardingHAL whose "link" is a function call to a HAL in the same process (the reference
// HAL), with every answer copied as a wire would, a switch to take the link down, and a record
// of what was sent. Only for the base's unit tests; the real transports are NatsHAL and RemoteHAL.
import { HalError, callMethod, invokeSpec, scoped } from '@hal/types';
import type {
  CallSpec,
  CallTable,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  HardwareAbstractionLayer,
  Logger,
  SafetyStatus,
} from '@hal/types';
import { ReferenceHAL } from '@hal/types/testing';
import { ForwardingHAL } from './forwarding-hal.js';
import type { HostLatchPolicy, SendOptions } from './forwarding-hal.js';

export interface LoopbackOptions {
  latch?: HostLatchPolicy;
  calls?: CallTable;
  /** Whether cleanup() stops the robot (false: a client that only watches). Default true. */
  stopsOnCleanup?: boolean;
  /** Replaces the served HAL's answer to a call (to make it fail, hang or lie). */
  answer?: (spec: CallSpec, args: unknown[]) => Promise<unknown> | undefined;
  logger?: Logger;
}

export class LoopbackHAL extends ForwardingHAL {
  /** The HAL "at the other end", initialised by the first open(). */
  readonly served: HardwareAbstractionLayer;
  /** Every call sent, by name, in order (`log` included). */
  readonly sent: string[] = [];
  /** The timeout each call was sent with (undefined: the transport's own). */
  readonly timeouts: Array<number | undefined> = [];
  /** Whether the link is up; set false to take it down. */
  up = true;
  readonly #options: LoopbackOptions;
  #open = false;
  #lastSafety: SafetyStatus | undefined;

  constructor(
    options: LoopbackOptions = {},
    served: HardwareAbstractionLayer = new ReferenceHAL(),
  ) {
    const log: Logger = options.logger ?? { log: () => undefined };
    super({
      calls: options.calls,
      latch: options.latch ?? 'until-reset',
      log: scoped(log, 'test'),
    });
    this.#options = options;
    this.served = served;
  }

  get mode(): HALMode {
    return this.served.mode;
  }

  /** Whether the link is open (between open() and close()). */
  get linkOpen(): boolean {
    return this.#open;
  }

  getDeviceInfo(): DeviceInfo {
    return this.served.getDeviceInfo();
  }

  /** The link comes back (after `up = false`): what a transport does on reconnecting. */
  reconnect(): void {
    this.up = true;
    this.linkRestored();
  }

  protected async open(): Promise<void> {
    if (!this.up) throw new HalError('NOT_CONNECTED', 'the loopback link is down');
    if (!this.served.isReady()) await this.served.initialize();
    this.#open = true;
  }

  protected async close(): Promise<void> {
    this.#open = false;
  }

  protected reachable(): boolean {
    return this.#open && this.up;
  }

  protected override linkDown(): HalError | undefined {
    return this.up ? undefined : new HalError('NOT_CONNECTED', 'the loopback link is down');
  }

  protected override stopsOnCleanup(): boolean {
    return this.#options.stopsOnCleanup ?? true;
  }

  protected servedSafety(): SafetyStatus | undefined {
    return this.#lastSafety;
  }

  protected async send(spec: CallSpec, args: unknown[], options: SendOptions = {}) {
    this.sent.push(spec.name);
    this.timeouts.push(options.timeoutMs);
    if (!this.up || !this.#open) throw new HalError('NOT_CONNECTED', 'the loopback link is down');
    const answer =
      this.#options.answer?.(spec, args) ?? invokeSpec(this.served, spec, structuredClone(args));
    const value: unknown = await answer;
    this.#lastSafety = structuredClone(this.served.safety.getSafetyStatus());
    return structuredClone(value);
  }

  protected sendLog(message: string, level: HALLogLevel | undefined): void {
    this.sent.push('log');
    const spec = { subsystem: 'communication', method: 'log', name: 'log' } as CallSpec;
    callMethod(this.served, spec, [message, level]);
  }
}
