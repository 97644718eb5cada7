// A HardwareAbstractionLayer whose robot is served by serveHal() in another process. Node and
// browser: it never imports `ws` statically.
import {
  HAL_CALL_TABLE,
  HALToolResultSchema,
  HalError,
  failureResult,
  forwardCalls,
  isHalError,
  sanitizeEstopReason,
  successResult,
  scoped,
  silentLogger,
} from '@hal/types';
import type {
  CallSpec,
  CommunicationInterface,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  HALToolResult,
  HardwareAbstractionLayer,
  LocomotionInterface,
  SafetyInterface,
  SafetyStatus,
  VisionInterface,
} from '@hal/types';
import type { Role } from '../protocol.js';
import { Connection } from './connection.js';
import { REMOTE_DEFAULTS } from './options.js';
import type { RemoteHALOptions } from './options.js';

const UNKNOWN_SAFETY: SafetyStatus = { emergencyStopped: false, batteryLevel: 100, errors: [] };

export class RemoteHAL implements HardwareAbstractionLayer {
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;

  readonly #options: Required<Omit<RemoteHALOptions, 'token' | 'WebSocket' | 'calls'>> &
    Pick<RemoteHALOptions, 'token' | 'WebSocket'>;
  /** The calls by name, for their kind and result schema. */
  readonly #calls: ReadonlyMap<string, CallSpec>;
  readonly #link: Connection;
  #initialized = false;
  /**
   * The host's e-stop latch: the sanitized reason of an `emergencyStop()` the server has not yet
   * confirmed (called before `initialize()`, after `cleanup()`, or while the link was down). It
   * refuses motion here at once; the next connection sends it to the server, and once the served
   * HAL has latched, the served state says so. An accepted `resetEmergencyStop()` clears it.
   */
  #hostEstop: string | undefined;
  /** The e-stop being sent to the server, if one is on its way. */
  #delivering: Promise<boolean> | undefined;

  constructor(options: RemoteHALOptions) {
    this.#options = { ...REMOTE_DEFAULTS, logger: silentLogger, ...options };
    this.#link = new Connection({
      url: options.url,
      token: options.token,
      WebSocket: options.WebSocket,
      clientId: this.#options.clientId,
      watchOnly: this.#options.control === 'watch',
      connectTimeoutMs: this.#options.connectTimeoutMs,
      reconnect: this.#options.reconnect,
      reconnectDelayMs: this.#options.reconnectDelayMs,
      logger: this.#options.logger,
      onConnected: () => this.#onConnected(),
    });
    const table = options.calls ?? HAL_CALL_TABLE;
    this.#calls = new Map(table.map((spec) => [spec.name, spec]));
    const subsystems = forwardCalls(
      (spec, args) =>
        spec.kind === 'value' ? this.#value(spec.name, args) : this.#result(spec.name, args),
      {
        log: (message: string, level?: HALLogLevel) => this.#remoteLog(message, level),
        emergencyStop: (reason?: unknown) => this.#emergencyStop(reason),
        resetEmergencyStop: () => this.#resetEmergencyStop(),
        isEmergencyStopped: () => this.#cachedSafety().emergencyStopped,
        getSafetyStatus: () => this.#cachedSafety(),
      },
      table,
    );
    this.locomotion = subsystems.locomotion;
    this.vision = subsystems.vision;
    this.communication = subsystems.communication;
    this.safety = subsystems.safety;
  }

  /** The served HAL's mode (known once connected). */
  get mode(): HALMode {
    return this.#link.hello?.mode ?? this.#options.mode;
  }

  /** Whether this client controls the robot or watches it. */
  get role(): Role {
    return this.#link.role;
  }

  /** Calls `listener` when this client gains or loses control. Returns an unsubscribe function. */
  onRoleChange(listener: (role: Role, reason: string) => void): () => void {
    this.#link.roleListeners.add(listener);
    return () => this.#link.roleListeners.delete(listener);
  }

  /** Takes control of the robot; the previous controller is told and becomes a watcher. */
  async takeControl(): Promise<void> {
    await this.#link.request('take_control', [], this.#options.requestTimeoutMs);
  }

  async initialize(): Promise<void> {
    if (this.isReady()) return;
    this.#initialized = true;
    try {
      await this.#link.open();
      if (this.#options.control === 'take') await this.takeControl();
      // emergencyStop() was called before initialize() (or after a cleanup, or while the link was
      // down): latch the served HAL too before reporting ready
      if (this.#hostEstop !== undefined && !(await this.#deliverEstop())) {
        throw new HalError('NOT_CONNECTED', 'could not send the pending emergency stop');
      }
    } catch (e) {
      this.#initialized = false;
      this.#link.close();
      throw isHalError(e) ? e : new HalError('NOT_CONNECTED', String(e), { cause: e });
    }
  }

  async cleanup(): Promise<void> {
    if (!this.#initialized) return;
    this.#initialized = false;
    if (this.#link.connected && this.#link.role === 'controller') {
      // Leave the robot still: a controller going away stops its motion (the server would too).
      await this.#link.request('stop', [], this.#options.requestTimeoutMs).catch(() => undefined);
    }
    this.#link.close();
  }

  isReady(): boolean {
    return this.#initialized && this.#link.connected;
  }

  getDeviceInfo(): DeviceInfo {
    const device = this.#link.hello?.device;
    if (device !== undefined) return { ...device, capabilities: [...device.capabilities] };
    return { id: this.#options.clientId, type: 'remote', mode: this.mode, capabilities: [] };
  }

  #onConnected(): void {
    this.#link.send('hal.remote.subscribe', { state: true });
    if (this.#options.control === 'take' && this.#initialized && this.#link.role !== 'controller') {
      this.takeControl().catch(() => undefined);
    }
    // a reconnection: send an e-stop the server has not confirmed (initialize() sends its own)
    if (this.#initialized && this.#hostEstop !== undefined && this.isReady()) {
      void this.#deliverEstop();
    }
  }

  #cachedSafety(): SafetyStatus {
    const served = this.#link.safety ?? UNKNOWN_SAFETY;
    const safety: SafetyStatus = { ...served, errors: [...served.errors] };
    if (served.emergencyStopReason !== undefined) {
      safety.emergencyStopReason = sanitizeEstopReason(served.emergencyStopReason);
    }
    if (this.#hostEstop !== undefined) {
      safety.emergencyStopped = true;
      if (!served.emergencyStopped || safety.emergencyStopReason === undefined) {
        safety.emergencyStopReason = this.#hostEstop;
      }
    }
    return safety;
  }

  /**
   * Never refused: latches on the host at once, then sends the sanitized reason to the server if
   * connected. Without a link it succeeds with `delivered: false`; the next connection sends it.
   */
  async #emergencyStop(reason: unknown): Promise<HALToolResult> {
    const started = Date.now();
    const stored = sanitizeEstopReason(reason);
    this.#hostEstop = stored;
    if (this.isReady()) {
      try {
        const result = await this.#send('emergencyStop', [stored]);
        if (result.success) {
          if (this.#hostEstop === stored) this.#hostEstop = undefined; // the served HAL holds it
          const data: Record<string, unknown> = { ...result.data, delivered: true };
          if (typeof data['reason'] === 'string')
            data['reason'] = sanitizeEstopReason(data['reason']);
          return { ...result, data };
        }
        scoped(this.#options.logger, 'hal:remote:client').warn('the server refused an e-stop', {
          error: result.error,
        });
      } catch (e) {
        scoped(this.#options.logger, 'hal:remote:client').warn('e-stop not delivered', {
          error: String(e),
        });
      }
    }
    return successResult(
      this.mode,
      Date.now(),
      { estop: true, reason: stored, delivered: false },
      Date.now() - started,
    );
  }

  /** Sends the host's latch to the server; true once the served HAL has it. */
  #deliverEstop(): Promise<boolean> {
    const reason = this.#hostEstop;
    if (reason === undefined) return Promise.resolve(true);
    this.#delivering ??= (async () => {
      try {
        const result = await this.#send('emergencyStop', [reason]);
        if (!result.success) return false;
        if (this.#hostEstop === reason) this.#hostEstop = undefined;
        return true;
      } catch (e) {
        scoped(this.#options.logger, 'hal:remote:client').warn('e-stop not delivered', {
          error: String(e),
        });
        return false;
      } finally {
        this.#delivering = undefined;
      }
    })();
    return this.#delivering;
  }

  /** Clears the served HAL's latch, and the host's once the server accepts. */
  async #resetEmergencyStop(): Promise<HALToolResult> {
    if (this.#delivering !== undefined) await this.#delivering;
    const result = await this.#result('resetEmergencyStop', []);
    if (result.success) this.#hostEstop = undefined;
    return result;
  }

  #refusal(): HalError | undefined {
    if (!this.#initialized) {
      return new HalError('NOT_READY', 'the remote HAL is not initialised: call initialize()');
    }
    if (!this.#link.connected) {
      return new HalError('NOT_CONNECTED', `not connected to ${this.#options.url}; reconnecting`);
    }
    return undefined;
  }

  #isMotion(call: string): boolean {
    return this.#calls.get(call)?.kind === 'motion';
  }

  #timeout(call: string): number {
    return this.#isMotion(call) ? this.#options.motionTimeoutMs : this.#options.requestTimeoutMs;
  }

  async #result(call: string, args: unknown[]): Promise<HALToolResult> {
    const started = Date.now();
    const refusal = this.#refusal();
    if (refusal !== undefined) return failureResult(this.mode, Date.now(), refusal, 0);
    if (this.#hostEstop !== undefined && this.#isMotion(call)) {
      const latched = new HalError(
        'EMERGENCY_STOPPED',
        'emergency stop is active: reset it first',
        {
          details: { reason: this.#hostEstop },
        },
      );
      return failureResult(this.mode, Date.now(), latched, 0);
    }
    try {
      return await this.#send(call, args);
    } catch (e) {
      return failureResult(this.mode, Date.now(), e, Date.now() - started);
    }
  }

  /** Runs a result call on the server; rejects if it has no valid answer. */
  async #send(call: string, args: unknown[]): Promise<HALToolResult> {
    const value = await this.#link.request(call, args, this.#timeout(call));
    const parsed = HALToolResultSchema.safeParse(value);
    if (!parsed.success) {
      throw new HalError('MALFORMED', `the server's "${call}" result is not a HALToolResult`);
    }
    return parsed.data as HALToolResult;
  }

  async #value(call: string, args: unknown[]): Promise<unknown> {
    const refusal = this.#refusal();
    if (refusal !== undefined) throw refusal;
    const value = await this.#link.request(call, args, this.#timeout(call));
    const schema = this.#calls.get(call)?.data;
    if (schema === undefined) return value;
    const parsed = schema.safeParse(value);
    if (!parsed.success) {
      throw new HalError('MALFORMED', `the server's "${call}" answer does not match its schema`, {
        details: { issue: parsed.error.issues[0]?.message },
      });
    }
    return parsed.data;
  }

  #remoteLog(message: string, level?: HALLogLevel): void {
    try {
      const refusal = this.#refusal();
      if (refusal !== undefined) {
        scoped(this.#options.logger, 'hal:remote:client').warn(`log refused: ${refusal.message}`);
        return;
      }
      this.#link
        .request('log', [message, level], this.#options.requestTimeoutMs)
        .catch((e: unknown) => {
          scoped(this.#options.logger, 'hal:remote:client').warn('log refused', {
            error: String(e),
          });
        });
    } catch (e) {
      scoped(this.#options.logger, 'hal:remote:client').warn('log failed', {
        error: String(e),
      });
    }
  }
}
