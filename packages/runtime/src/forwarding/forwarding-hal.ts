import {
  EstopLatch,
  HAL_CALL_TABLE,
  HALToolResultSchema,
  HalBoundary,
  HalError,
  V1_ROBOT,
  failureResult,
  forwardCalls,
  isHalError,
  objectFromArgs,
  sanitizeEstopReason,
  successResult,
} from '@hal/types';
import type {
  CallName,
  CallSpec,
  CallTable,
  CommunicationInterface,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  HALToolResult,
  HardwareAbstractionLayer,
  LocomotionInterface,
  SafetyInterface,
  SafetyStatus,
  ScopedLogger,
  VisionInterface,
} from '@hal/types';

/**
 * How long the host's e-stop latch is the host's own:
 * - `until-reset`: held here until this HAL's reset is accepted (one client per robot);
 * - `until-served`: held here until the served HAL confirms it holds the stop, and sent again on
 *   every reconnection until then. Where several clients share a served HAL, any of them may
 *   reset it, so once it holds the stop its state is the truth.
 */
export type HostLatchPolicy = 'until-reset' | 'until-served';

export interface ForwardingHALOptions {
  /** The calls forwarded; default the HAL's own call table. */
  calls?: CallTable | undefined;
  latch: HostLatchPolicy;
  /** Where refusals and undelivered e-stops are written. */
  log: ScopedLogger;
}

/** What a send may be told, for the calls the base makes itself. */
export interface SendOptions {
  /** Wait at most this long, ms (the transport's own timeout still applies if shorter). */
  timeoutMs?: number;
}

/** The safety status reported before the served HAL has said its own. */
const UNKNOWN_SAFETY: SafetyStatus = Object.freeze({
  emergencyStopped: false,
  batteryLevel: 100,
  errors: [],
}) as SafetyStatus;

/** The stop sent on cleanup is bounded: a robot that is gone must not hold cleanup up. */
const STOP_ON_CLEANUP_MS = 2000;
/** The e-stop latched before `initialize()` must reach the robot within this, or it fails. */
const PENDING_ESTOP_MS = 5000;

function specOf(table: CallTable, name: string): CallSpec {
  const spec = table.find((entry) => entry.name === name);
  if (spec === undefined)
    throw new HalError('INVALID_PARAMETER', `the call table has no "${name}"`);
  return spec;
}

/**
 * The base of every HAL that sends its calls to a HAL elsewhere (over WebSocket, over NATS). A
 * subclass supplies its transport: {@link open}, {@link close}, {@link send} and
 * {@link sendLog}, and what the served HAL last said of its safety. The base owns the rest, the
 * same for every transport, and every call goes through {@link HalBoundary}:
 * - before `initialize()` and after `cleanup()` every call is refused NOT_READY;
 * - the e-stop is never refused: it latches on this host at once (motion is refused here
 *   whatever the link does), stores its reason sanitized, and goes to the served HAL with
 *   priority; unconnected, it answers success with `delivered: false` and the next
 *   `initialize()` latches the served HAL before reporting ready; only an accepted reset clears
 *   the host's latch (see {@link HostLatchPolicy});
 * - `isEmergencyStopped()` and `getSafetyStatus()` answer at once from the host's latch and the
 *   served HAL's last word, with reasons sanitized;
 * - `cleanup()` stops the robot (bounded) before letting go of the link;
 * - a result is checked to be a HALToolResult, a value against its call's schema (MALFORMED).
 * Parameters are validated by the served HAL, which knows its robot's limits.
 */
export abstract class ForwardingHAL implements HardwareAbstractionLayer {
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  abstract get mode(): HALMode;

  readonly #boundary: HalBoundary;
  readonly #calls: CallTable;
  readonly #policy: HostLatchPolicy;
  readonly #log: ScopedLogger;
  #initialized = false;
  /** The host's latch (its sanitized reason): set by emergencyStop() before anything is sent. */
  readonly #latch = new EstopLatch();
  /** The pending e-stop being sent to the served HAL, if one is on its way. */
  #delivering: Promise<void> | undefined;

  protected constructor(options: ForwardingHALOptions) {
    this.#calls = options.calls ?? HAL_CALL_TABLE;
    this.#policy = options.latch;
    this.#log = options.log;
    const mode = () => this.mode;
    this.#boundary = new HalBoundary({
      get mode() {
        return mode();
      },
      config: () => V1_ROBOT, // unused: validateParams is off
      validateParams: false,
      isEmergencyStopped: () => this.#latch.latched,
      isReady: () => this.#initialized,
      calls: this.#calls,
    });
    const subsystems = forwardCalls(
      (spec, args) => (spec.kind === 'value' ? this.#value(spec, args) : this.#result(spec, args)),
      {
        log: (message: string, level?: HALLogLevel) => this.#sendLog(message, level),
        emergencyStop: (reason?: unknown) =>
          this.#boundary.forward('emergencyStop', () => this.#emergencyStop(reason)),
        resetEmergencyStop: () => this.#resetEmergencyStop(),
        isEmergencyStopped: () => this.#safetyStatus().emergencyStopped,
        getSafetyStatus: () => this.#safetyStatus(),
      },
      this.#calls,
    );
    this.locomotion = subsystems.locomotion;
    this.vision = subsystems.vision;
    this.communication = subsystems.communication;
    this.safety = subsystems.safety;
  }

  /** Opens the link and learns the served HAL; rejects (NOT_CONNECTED, ...) when it is not there. */
  protected abstract open(): Promise<void>;
  /** Lets go of the link. Safe to call when it is not open. */
  protected abstract close(): Promise<void>;
  /**
   * Sends one call and answers what the served HAL answered: a HALToolResult (motion and result
   * calls) or a value (value calls); rejects with a HalError when it has no answer (a rejected
   * promise, never a synchronous throw).
   */
  protected abstract send(spec: CallSpec, args: unknown[], options?: SendOptions): Promise<unknown>;
  /** Sends a log message, unanswered; reports its own failures through its logger. */
  protected abstract sendLog(message: string, level: HALLogLevel | undefined): void;
  /** What the served HAL last said of its safety (undefined: nothing yet). */
  protected abstract servedSafety(): Partial<SafetyStatus> | undefined;
  /** Whether the served HAL can be reached now (part of `isReady()`). */
  protected abstract reachable(): boolean;
  abstract getDeviceInfo(): DeviceInfo;

  /**
   * Why calls cannot go out now although the HAL is initialised (the link is down and
   * reconnecting), or undefined to let the transport try. Default undefined.
   */
  protected linkDown(): HalError | undefined {
    return undefined;
  }

  /** Whether `cleanup()` stops the robot (a client that only watches must not). Default true. */
  protected stopsOnCleanup(): boolean {
    return true;
  }

  /** The subclass's link is back: an e-stop the served HAL has not confirmed is sent again. */
  protected linkRestored(): void {
    if (this.#policy === 'until-served' && this.isReady() && this.#latch.latched) {
      void this.#deliverPending().catch((e: unknown) => {
        this.#log.warn('e-stop not delivered', { error: String(e) });
      });
    }
  }

  async initialize(): Promise<void> {
    if (this.isReady()) return;
    this.#initialized = true;
    try {
      await this.open();
      // an e-stop latched while not connected: the served HAL latches too before we are ready
      if (this.#latch.latched) await this.#deliverPending();
    } catch (error) {
      this.#initialized = false;
      await this.close().catch(() => undefined);
      throw isHalError(error)
        ? error
        : new HalError('NOT_CONNECTED', String(error), { cause: error });
    }
  }

  /** Stops the robot (best effort, bounded) and lets go of the link. Safe to call twice. */
  async cleanup(): Promise<void> {
    if (!this.#initialized) return;
    this.#initialized = false;
    if (this.stopsOnCleanup()) {
      const stop = specOf(this.#calls, 'stop');
      try {
        await this.send(stop, [], { timeoutMs: STOP_ON_CLEANUP_MS });
      } catch {
        // best effort: a robot that cannot be reached cannot be stopped from here
      }
    }
    await this.close();
  }

  isReady(): boolean {
    return this.#initialized && this.reachable();
  }

  #safetyStatus(): SafetyStatus {
    const served = { ...UNKNOWN_SAFETY, ...this.servedSafety() };
    const status: SafetyStatus = { ...served, errors: [...served.errors] };
    if (served.emergencyStopReason !== undefined) {
      status.emergencyStopReason = sanitizeEstopReason(served.emergencyStopReason);
    }
    const held = this.#latch.reason;
    if (held !== undefined) {
      status.emergencyStopped = true;
      if (!served.emergencyStopped || status.emergencyStopReason === undefined) {
        status.emergencyStopReason = held;
      }
    }
    return status;
  }

  // The bodies below are plain functions returning promises, not async ones: every forwarded call
  // comes through here, and the boundary already turns a throw into a failure or a rejection.
  #result(spec: CallSpec, args: unknown[], options?: SendOptions): Promise<HALToolResult> {
    return this.#boundary.forward(spec.name as CallName, () => {
      const down = this.linkDown();
      if (down !== undefined) throw down;
      return this.#sendResult(spec, args, options);
    });
  }

  #sendResult(spec: CallSpec, args: unknown[], options?: SendOptions): Promise<HALToolResult> {
    return this.send(spec, args, options).then((answer) => {
      const parsed = HALToolResultSchema.safeParse(answer);
      if (!parsed.success) {
        throw new HalError('MALFORMED', `the served "${spec.name}" answer is not a HALToolResult`);
      }
      return parsed.data as HALToolResult;
    });
  }

  #value(spec: CallSpec, args: unknown[]): Promise<unknown> {
    return this.#boundary.read(spec.name as CallName, objectFromArgs(spec, args), () => {
      const down = this.linkDown();
      if (down !== undefined) throw down;
      return this.send(spec, args).then((answer) => {
        const parsed = spec.data.safeParse(answer);
        if (!parsed.success) {
          throw new HalError(
            'MALFORMED',
            `the served "${spec.name}" answer does not match its schema`,
            { details: { issue: parsed.error.issues[0]?.message } },
          );
        }
        return parsed.data;
      });
    });
  }

  #sendLog(message: string, level: HALLogLevel | undefined): void {
    const args = [message, level];
    const result = this.#boundary.notify(
      'log',
      objectFromArgs(specOf(this.#calls, 'log'), args),
      () => {
        const down = this.linkDown();
        if (down !== undefined) throw down;
        this.sendLog(message, level);
      },
    );
    if (!result.success) this.#log.warn(`log refused: ${result.error ?? ''}`);
  }

  /**
   * Never refused: latches on the host at once, then sends the sanitized reason to the served
   * HAL if connected. Unconnected it succeeds with `delivered: false`; `initialize()` sends it.
   */
  async #emergencyStop(reason: unknown): Promise<HALToolResult> {
    const started = Date.now();
    const stored = sanitizeEstopReason(reason);
    this.#latch.latch(stored);
    const undelivered = () =>
      successResult(
        this.mode,
        Date.now(),
        { estop: true, reason: stored, delivered: false },
        Date.now() - started,
      );
    if (!this.#initialized || this.linkDown() !== undefined) return undelivered();
    let result: HALToolResult;
    try {
      result = await this.#sendResult(specOf(this.#calls, 'emergencyStop'), [stored]);
    } catch (error) {
      if (this.#policy === 'until-reset') {
        return failureResult(this.mode, Date.now(), error, Date.now() - started);
      }
      // until-served: the latch holds here and goes again when the link is back
      this.#log.warn('e-stop not delivered', { error: String(error) });
      return undelivered();
    }
    if (!result.success) {
      if (this.#policy === 'until-reset') return result;
      this.#log.warn('the served HAL refused an e-stop', { error: result.error });
      return undelivered();
    }
    this.#served(stored);
    const told = result.data?.['reason'];
    const data = {
      ...result.data,
      reason: typeof told === 'string' ? sanitizeEstopReason(told) : stored,
      delivered: true,
    };
    return { ...result, data };
  }

  /** The served HAL holds the stop of `reason`: under `until-served` the host lets go of it. */
  #served(reason: string): void {
    if (this.#policy === 'until-served') this.#latch.release(reason);
  }

  /** Sends the host's latch to the served HAL (one send at a time); rejects unless it took it. */
  #deliverPending(): Promise<void> {
    const reason = this.#latch.reason;
    if (reason === undefined) return Promise.resolve();
    this.#delivering ??= (async () => {
      try {
        const spec = specOf(this.#calls, 'emergencyStop');
        const result = await this.#sendResult(spec, [reason], { timeoutMs: PENDING_ESTOP_MS });
        if (!result.success) {
          throw new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? 'e-stop refused', {
            ...(result.details === undefined ? {} : { details: result.details }),
          });
        }
        this.#served(reason);
      } catch (error) {
        if (isHalError(error) && error.code !== 'TIMEOUT') throw error;
        throw new HalError('NOT_CONNECTED', 'the served HAL did not take the pending e-stop', {
          cause: error,
        });
      } finally {
        this.#delivering = undefined;
      }
    })();
    return this.#delivering;
  }

  /** Clears the served HAL's latch, and the host's once the served HAL accepts. */
  async #resetEmergencyStop(): Promise<HALToolResult> {
    if (this.#delivering !== undefined) await this.#delivering.catch(() => undefined);
    const result = await this.#result(specOf(this.#calls, 'resetEmergencyStop'), []);
    if (result.success) this.#latch.reset();
    return result;
  }
}
