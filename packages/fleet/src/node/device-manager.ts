import { openConnection } from '@hal/nats';
import type { NatsConnectionSource } from '@hal/nats';
import {
  deadline,
  forwardCalls,
  HalError,
  scoped,
  silentLogger,
  toHalError,
  TypedEmitter,
} from '@hal/types';
import type { HardwareAbstractionLayer, Logger, ScopedLogger } from '@hal/types';
import { Fleet } from '../fleet.js';
import type { FleetOptions } from '../fleet.js';
import { createDeviceHAL, definedFields } from './create-device-hal.js';
import type { DeviceFactories } from './create-device-hal.js';
import { parseDeviceConfig, parseFleetConfig } from './device-config.js';
import type { DeviceConfig, FleetConfig, FleetConfigInput } from './device-config.js';
import type { DeviceHealth, DeviceManagerEvents, DeviceTelemetry } from './device-status.js';
import { OfflineGuardHAL } from './offline-guard.js';

/** How long releasing a device's HAL may take before the manager moves on, ms. */
const CLEANUP_TIMEOUT_MS = 5000;

export interface DeviceManagerOptions {
  /** Builders of the simulated and physical devices (NATS devices need none). */
  devices?: DeviceFactories;
  /** An open NATS connection for the "nats" devices (not closed by the manager). */
  natsConnection?: NatsConnectionSource;
  logger?: Logger;
  natsLogger?: Logger;
  /** Options of the fleet the manager drives (scheduler, timeouts). */
  fleet?: Omit<FleetOptions, 'logger'>;
  /**
   * Wraps each device's HAL as it is built (a flight recorder, a tracer): every call the fleet
   * makes, and the device's `initialize` and `cleanup`, go through what it returns. The
   * manager's own telemetry reads (pose and safety at `telemetryRateHz`) go to the device's HAL
   * itself, so they are not seen as calls of the run.
   */
  wrapDevice?: (device: string, hal: HardwareAbstractionLayer) => HardwareAbstractionLayer;
}

interface Managed {
  config: DeviceConfig;
  /** The device's HAL as built: what the telemetry reads. */
  device: HardwareAbstractionLayer;
  /** The same, through `wrapDevice` when given: what is initialised, called and cleaned up. */
  raw: HardwareAbstractionLayer;
  guarded: OfflineGuardHAL;
  online: boolean;
  initialized: boolean;
  busy: boolean;
  /** A connection attempt still running (never two at once: a HAL's initialize is not reentrant). */
  initializing?: Promise<void> | undefined;
  lastSeen?: number;
  telemetry?: DeviceTelemetry;
  lastError?: string;
}

type Listener<E extends keyof DeviceManagerEvents> = (event: DeviceManagerEvents[E]) => void;

/**
 * The fleet's devices, from config: each routed to its HAL (NatsHAL, or what the `devices`
 * builders make of a simulated or physical device), read at `telemetryRateHz` (pose, safety), seen online or offline (events), and
 * driven in the fleet modes through {@link fleet}. A call to an offline device fails at once
 * with NOT_CONNECTED, details `{ device, offline: true }`; the fleet e-stop reaches every device.
 */
export class DeviceManager {
  readonly config: FleetConfig;
  /** The fleet modes over the managed devices (their offline-guarded HALs). */
  readonly fleet: Fleet;
  readonly #devices = new Map<string, Managed>();
  readonly #events: TypedEmitter<DeviceManagerEvents>;
  readonly #log: ScopedLogger;
  readonly #options: DeviceManagerOptions;
  #nats: { source: NatsConnectionSource; close?: () => Promise<void> } | undefined;
  #timer: ReturnType<typeof setInterval> | undefined;
  #started = false;

  constructor(config: FleetConfigInput | FleetConfig = {}, options: DeviceManagerOptions = {}) {
    this.config = parseFleetConfig(config);
    this.#options = options;
    const logger = options.logger ?? silentLogger;
    this.#log = scoped(logger, 'hal:fleet:devices');
    this.#events = new TypedEmitter<DeviceManagerEvents>((event, error) =>
      this.#log.error('a device event listener threw', { event, error: toHalError(error).message }),
    );
    this.fleet = new Fleet([], { ...options.fleet, logger });
    if (options.natsConnection !== undefined) this.#nats = { source: options.natsConnection };
    const onNats = this.config.devices.find((d) => d.type === 'nats');
    if (onNats !== undefined && this.#nats === undefined && this.config.nats === undefined) {
      throw new HalError(
        'INVALID_PARAMETER',
        `fleet config: nats: device "${onNats.id}" is on NATS: give "nats.servers" (or an open connection)`,
        { details: { device: onNats.id, parameter: 'nats' } },
      );
    }
    for (const device of this.config.devices) this.#add(device);
  }

  /** The managed device ids, in registration order. */
  get devices(): string[] {
    return [...this.#devices.keys()];
  }

  /** Registers a device (checked: INVALID_PARAMETER naming the field); connected on the next round. */
  register(input: unknown): void {
    const config = parseDeviceConfig(input);
    if (this.#devices.has(config.id)) {
      throw new HalError('INVALID_PARAMETER', `device "${config.id}" is already registered`, {
        details: { device: config.id },
      });
    }
    if (config.type === 'nats' && this.#nats === undefined && this.config.nats === undefined) {
      throw new HalError(
        'INVALID_PARAMETER',
        `device "${config.id}" is on NATS: no NATS servers given`,
        {
          details: { device: config.id, parameter: 'nats' },
        },
      );
    }
    this.#add(config);
    if (this.#started) void this.#poll(this.#devices.get(config.id) as Managed);
  }

  /** Removes a device, stopping it and releasing its HAL. Returns whether it was registered. */
  async unregister(id: string): Promise<boolean> {
    const managed = this.#devices.get(id);
    if (managed === undefined) return false;
    this.#devices.delete(id);
    this.fleet.remove(id);
    await deadline(managed.raw.cleanup(), CLEANUP_TIMEOUT_MS, `cleanup of "${id}"`).catch(
      () => undefined,
    );
    return true;
  }

  /**
   * The HAL of one device, as every caller should use it (offline: NOT_CONNECTED at once). The
   * device keeps one HAL, and so one controlling session. Unknown id: INVALID_PARAMETER.
   */
  createDeviceHAL(id: string): HardwareAbstractionLayer {
    return this.#get(id).guarded;
  }

  /** Whether a device answered within `offlineAfterMs`. */
  isOnline(id: string): boolean {
    return this.#get(id).online;
  }

  /** Every device's health, in registration order. */
  health(): DeviceHealth[] {
    return [...this.#devices.values()].map((m) => {
      const h: DeviceHealth = {
        device: m.config.id,
        type: m.config.type,
        online: m.online,
        ready: m.guarded.isReady(),
        emergencyStopped: m.device.safety.isEmergencyStopped(),
      };
      if (m.lastSeen !== undefined) h.lastSeen = m.lastSeen;
      if (m.telemetry !== undefined) h.telemetry = m.telemetry;
      if (m.lastError !== undefined) h.lastError = m.lastError;
      return h;
    });
  }

  /**
   * Calls `listener` on every `event`; returns the function that unsubscribes it. A listener that
   * throws is logged and stops neither the other listeners nor the manager.
   */
  on<E extends keyof DeviceManagerEvents>(event: E, listener: Listener<E>): () => void {
    return this.#events.on(event, listener);
  }

  /**
   * Connects every device (in parallel, each bounded) and starts the telemetry loop. Resolves
   * once every device has answered or failed its first attempt: devices not there stay offline
   * and are retried every round.
   */
  async start(): Promise<DeviceHealth[]> {
    if (this.#started) return this.health();
    this.#started = true;
    if (this.#nats === undefined && this.config.nats !== undefined) {
      const connection = await openConnection({
        ...definedFields(this.config.nats),
        servers: this.config.nats.servers,
        name: 'hal-fleet',
      });
      this.#nats = { source: { connection }, close: () => connection.close() };
      for (const m of this.#devices.values()) {
        if (m.config.type === 'nats') this.#rebuild(m); // now that NATS is open
      }
    }
    await Promise.all([...this.#devices.values()].map((m) => this.#poll(m)));
    const periodMs = 1000 / this.config.telemetryRateHz;
    this.#timer = setInterval(() => {
      for (const m of this.#devices.values()) void this.#poll(m);
    }, periodMs);
    return this.health();
  }

  /** Stops telemetry, stops and releases every device's HAL, and closes NATS if it opened it. */
  async stop(): Promise<void> {
    clearInterval(this.#timer);
    this.#timer = undefined;
    this.#started = false;
    await this.fleet.formation?.stop();
    await Promise.all(
      [...this.#devices.values()].map((m) =>
        deadline(m.raw.cleanup(), CLEANUP_TIMEOUT_MS, `cleanup of "${m.config.id}"`).catch(
          (e: unknown) => {
            this.#log.warn('cleanup failed', { device: m.config.id, error: toHalError(e).message });
          },
        ),
      ),
    );
    this.#options.devices?.released?.();
    await this.#nats?.close?.();
    if (this.#nats?.close !== undefined) this.#nats = undefined;
  }

  /** The fleet-wide e-stop: every device latched at once (see {@link Fleet.emergencyStop}). */
  emergencyStop(reason?: string): ReturnType<Fleet['emergencyStop']> {
    return this.fleet.emergencyStop(reason);
  }

  #get(id: string): Managed {
    const managed = this.#devices.get(id);
    if (managed === undefined) {
      throw new HalError(
        'INVALID_PARAMETER',
        `no device "${id}" (devices: ${this.devices.join(', ') || 'none'})`,
        { details: { device: id, devices: this.devices } },
      );
    }
    return managed;
  }

  #add(config: DeviceConfig): void {
    const managed = { config, online: false, initialized: false, busy: false } as Managed;
    this.#build(managed);
    this.#devices.set(config.id, managed);
    this.fleet.add({ id: config.id, hal: managed.guarded });
  }

  #build(m: Managed): void {
    const nats = this.#nats?.source;
    const pending = m.config.type === 'nats' && nats === undefined;
    m.device = pending
      ? placeholderHAL()
      : createDeviceHAL(m.config, {
          ...(this.#options.devices === undefined ? {} : { devices: this.#options.devices }),
          ...(nats === undefined ? {} : { nats }),
          ...(this.#options.natsLogger === undefined
            ? {}
            : { natsLogger: this.#options.natsLogger }),
        });
    // a NATS device waiting for the connection is wrapped once it is built for real
    m.raw = pending ? m.device : (this.#options.wrapDevice?.(m.config.id, m.device) ?? m.device);
    m.guarded = new OfflineGuardHAL(m.raw, m.config.id, () => !m.online);
  }

  #rebuild(m: Managed): void {
    this.#build(m);
    this.fleet.remove(m.config.id);
    this.fleet.add({ id: m.config.id, hal: m.guarded });
  }

  #emit<E extends keyof DeviceManagerEvents>(event: E, payload: DeviceManagerEvents[E]): void {
    this.#events.emit(event, payload);
  }

  /** One round for one device: connect if needed, read, and update online/offline. */
  async #poll(m: Managed): Promise<void> {
    if (m.busy) return;
    m.busy = true;
    const waitMs = Math.min(this.config.offlineAfterMs, 5000);
    try {
      if (!m.initialized) {
        m.initializing ??= m.raw.initialize().finally(() => {
          m.initializing = undefined;
        });
        await deadline(m.initializing, waitMs, `initialize of "${m.config.id}"`);
        m.initialized = true;
      }
      const pose = await deadline(
        m.device.locomotion.getPose(),
        waitMs,
        `getPose of "${m.config.id}"`,
      );
      if (!m.device.isReady()) throw new HalError('NOT_CONNECTED', 'the HAL is not ready');
      const safety = m.device.safety.getSafetyStatus();
      const telemetry: DeviceTelemetry = {
        device: m.config.id,
        at: Date.now(),
        pose: { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw },
        velocity: { linear: pose.velocity.linear, angular: pose.velocity.angular },
        emergencyStopped: safety.emergencyStopped,
        errors: [...safety.errors],
      };
      if (safety.batteryLevel !== undefined) telemetry.batteryLevel = safety.batteryLevel;
      m.telemetry = telemetry;
      m.lastSeen = telemetry.at;
      delete m.lastError;
      if (!m.online && this.#devices.get(m.config.id) === m) {
        m.online = true;
        this.#log.info('device online', { device: m.config.id });
        this.#emit('online', { device: m.config.id });
      }
      this.#emit('telemetry', telemetry);
    } catch (thrown) {
      const error = toHalError(thrown);
      m.lastError = `${error.code}: ${error.message}`;
      const silentMs = Date.now() - (m.lastSeen ?? 0);
      if (m.online && silentMs >= this.config.offlineAfterMs) {
        m.online = false;
        this.#log.warn('device offline', { device: m.config.id, reason: m.lastError });
        this.#emit('offline', { device: m.config.id, reason: m.lastError });
      }
    } finally {
      m.busy = false;
    }
  }
}

/** Stands in for a NATS device until the connection is open (never called: guarded offline). */
function placeholderHAL(): HardwareAbstractionLayer {
  const refuse = (): Promise<never> =>
    Promise.reject(new HalError('NOT_CONNECTED', 'NATS is not connected yet'));
  const subsystems = forwardCalls(refuse, {
    log: () => undefined,
    isEmergencyStopped: () => false,
    getSafetyStatus: () => ({ emergencyStopped: false, batteryLevel: 0, errors: [] }),
  });
  return {
    mode: 'simulation',
    ...subsystems,
    initialize: refuse,
    cleanup: () => Promise.resolve(),
    isReady: () => false,
    getDeviceInfo: () => ({ id: 'pending', type: 'nats', mode: 'simulation', capabilities: [] }),
  };
}
