// A HardwareAbstractionLayer whose robot is served by serveHal() in another process. Node and
// browser: it never imports `ws` statically.
import { ForwardingHAL } from '@hal/runtime';
import type { SendOptions } from '@hal/runtime';
import { HalError, scoped, silentLogger } from '@hal/types';
import type {
  CallSpec,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  SafetyStatus,
  ScopedLogger,
} from '@hal/types';
import type { Role } from '../protocol.js';
import { Connection } from './connection.js';
import { REMOTE_DEFAULTS } from './options.js';
import type { RemoteHALOptions } from './options.js';

/**
 * A HAL served by `serveHal()`, over WebSocket. The latch, readiness, e-stop delivery and cleanup
 * are {@link ForwardingHAL}'s. Several clients share one served HAL (one controls, the others
 * watch), and any of them may reset its e-stop: so the host's latch is held only until the
 * served HAL confirms it holds the stop (`until-served`), and is sent again on every reconnection
 * until then.
 */
export class RemoteHAL extends ForwardingHAL {
  readonly #options: Required<Omit<RemoteHALOptions, 'token' | 'WebSocket' | 'calls'>> &
    Pick<RemoteHALOptions, 'token' | 'WebSocket'>;
  readonly #link: Connection;
  readonly #log: ScopedLogger;

  constructor(options: RemoteHALOptions) {
    const settings = { ...REMOTE_DEFAULTS, logger: silentLogger, ...options };
    const log = scoped(settings.logger, 'hal:remote:client');
    super({ calls: options.calls, latch: 'until-served', log });
    this.#options = settings;
    this.#log = log;
    this.#link = new Connection({
      url: options.url,
      token: options.token,
      WebSocket: options.WebSocket,
      clientId: settings.clientId,
      watchOnly: settings.control === 'watch',
      connectTimeoutMs: settings.connectTimeoutMs,
      reconnect: settings.reconnect,
      reconnectDelayMs: settings.reconnectDelayMs,
      logger: settings.logger,
      onConnected: () => this.#onConnected(),
    });
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

  getDeviceInfo(): DeviceInfo {
    const device = this.#link.hello?.device;
    if (device !== undefined) return { ...device, capabilities: [...device.capabilities] };
    return { id: this.#options.clientId, type: 'remote', mode: this.mode, capabilities: [] };
  }

  protected async open(): Promise<void> {
    await this.#link.open();
    if (this.#options.control === 'take') await this.takeControl();
  }

  protected async close(): Promise<void> {
    this.#link.close();
  }

  protected reachable(): boolean {
    return this.#link.connected;
  }

  protected override linkDown(): HalError | undefined {
    if (this.#link.connected) return undefined;
    return new HalError('NOT_CONNECTED', `not connected to ${this.#options.url}; reconnecting`);
  }

  /** A controller going away stops its motion (the server would too); a watcher must not. */
  protected override stopsOnCleanup(): boolean {
    return this.#link.connected && this.#link.role === 'controller';
  }

  protected servedSafety(): SafetyStatus | undefined {
    return this.#link.safety;
  }

  protected send(spec: CallSpec, args: unknown[], options: SendOptions = {}): Promise<unknown> {
    const own =
      spec.kind === 'motion' ? this.#options.motionTimeoutMs : this.#options.requestTimeoutMs;
    return this.#link.request(spec.name, args, Math.min(own, options.timeoutMs ?? own));
  }

  protected sendLog(message: string, level: HALLogLevel | undefined): void {
    this.#link
      .request('log', [message, level], this.#options.requestTimeoutMs)
      .catch((e: unknown) => this.#log.warn('log refused', { error: String(e) }));
  }

  #onConnected(): void {
    this.#link.send('hal.remote.subscribe', { state: true });
    if (this.#options.control === 'take' && this.isReady() && this.#link.role !== 'controller') {
      this.takeControl().catch(() => undefined);
    }
    // a reconnection: send an e-stop the server has not confirmed (initialize() sends its own)
    this.linkRestored();
  }
}
