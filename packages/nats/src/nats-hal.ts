import {
  HAL_CALL_TABLE,
  HalError,
  HALToolResultSchema,
  failureResult,
  forwardCalls,
  sanitizeEstopReason,
  successResult,
  scoped,
  silentLogger,
} from '@hal/types';
import type {
  CallTable,
  Logger,
  ScopedLogger,
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
import type { NatsConnection } from '@nats-io/transport-node';
import { decodeMessage, encodeArgs, encodeMessage } from './codec.js';
import type { NatsConnectionSource } from './connection.js';
import { resolveConnection } from './connection.js';
import { DeviceLink } from './device-link.js';
import { errorFromPayload } from './device-link.js';
import {
  CapabilityAnnouncementSchema,
  DifferentialStateSchema,
  HalCallReplySchema,
  SCHEMAS,
} from './messages.js';
import type { CapabilityAnnouncement } from './messages.js';
import { subjectFor } from './subjects.js';
import { crossesNats, natsCallName } from './hal-calls.js';

export type NatsHALOptions = NatsConnectionSource & {
  /** The device to drive (`hal.v1.dev.{deviceId}...`); omitted: the default device. */
  deviceId?: string;
  /** This client's id, sent as the envelope's `device_id`. Default `nats-hal-{random}`. */
  clientId?: string;
  /** Longest a call may take, ms (the longest motion plus margin). Default 120000. */
  callTimeoutMs?: number;
  /** Repeat an unanswered request (same request id, run once) after this long, ms. Default 2000. */
  attemptTimeoutMs?: number;
  /** The device is offline after this long without a word from it, ms. Default 3000. */
  offlineAfterMs?: number;
  /**
   * How often to tell the gateway this controller is alive, ms (it stops an open-ended drive of a
   * controller that goes quiet). Default 1000.
   */
  heartbeatMs?: number;
  logger?: Logger;
  /** The calls this HAL forwards; default the HAL's own call table. */
  calls?: CallTable;
};

let sequence = 0;
const STOP_ON_CLEANUP_MS = 2000;
/**
 * A {@link HardwareAbstractionLayer} that drives a device through NATS: every call goes to the
 * device's gateway (`serveHalOnNats`) and comes back with the device's own result. The same
 * agent code drives a robot on the desk or one across a building. A device that goes silent is
 * offline: its calls fail NOT_CONNECTED; nothing waits longer than `callTimeoutMs`.
 *
 * The e-stop is never refused: it latches on this host at once (motion is refused here whatever
 * the link does), stores its reason sanitized, and goes to the device with priority. Before
 * `initialize()` or after `cleanup()` it answers success with `delivered: false`, and the next
 * `initialize()` latches the device before it reports ready. Only an accepted reset clears it.
 */
export class NatsHAL implements HardwareAbstractionLayer {
  mode: HALMode = 'simulation';
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  readonly #options: NatsHALOptions;
  readonly #clientId: string;
  readonly #log: ScopedLogger;
  #link: DeviceLink | undefined;
  #nc: { nc: NatsConnection; owned: boolean } | undefined;
  #ready = false;
  #heartbeat: NodeJS.Timeout | undefined;
  #info: DeviceInfo;
  /** The device's own latch, as its last reply or state said. */
  #deviceEstopped = false;
  /** The reason the device stored, from our e-stop's reply. */
  #deviceReason: string | undefined;
  /**
   * The host's latch (its sanitized reason): set by emergencyStop() before anything is sent,
   * cleared only by an accepted reset. `initialize()` sends it to the device.
   */
  #hostLatch: string | undefined;
  #safety: SafetyStatus = { emergencyStopped: false, batteryLevel: 100, errors: [] };
  /** Calls that move the robot (by NATS name): refused at once while the host's latch is set. */
  readonly #motion: ReadonlySet<string>;
  /** Stop and e-stop (by NATS name): sent with priority. */
  readonly #safetyLane: ReadonlySet<string>;

  constructor(options: NatsHALOptions) {
    this.#options = options;
    this.#clientId = options.clientId ?? `nats-hal-${process.pid}-${(sequence += 1)}`;
    this.#log = scoped(options.logger ?? silentLogger, 'hal:nats:hal');
    if (options.deviceId !== undefined) subjectFor('call', options.deviceId); // checks the id
    this.#info = {
      id: options.deviceId ?? 'default',
      type: 'nats',
      mode: this.mode,
      capabilities: [],
    };
    const table = options.calls ?? HAL_CALL_TABLE;
    const names = (kind: (spec: CallTable[number]) => boolean) =>
      new Set(table.filter(kind).map(natsCallName));
    this.#motion = names((spec) => spec.kind === 'motion');
    this.#safetyLane = names((spec) => spec.lane === 'safety');
    const subsystems = forwardCalls(
      (spec, args) => {
        const call = natsCallName(spec);
        if (!crossesNats(spec)) {
          return Promise.reject(new HalError('NOT_IMPLEMENTED', `${call} does not cross NATS`));
        }
        return spec.kind === 'value' ? this.#value(call, args) : this.#result(call, args);
      },
      {
        log: (message: string, level?: HALLogLevel) => this.#sendLog(message, level),
        emergencyStop: (reason?: string) => this.#emergencyStop(reason),
        resetEmergencyStop: () => this.#resetEmergencyStop(),
        isEmergencyStopped: () => this.#isEstopped(),
        getSafetyStatus: () => this.#safetyStatus(),
      },
      table,
    );
    this.locomotion = subsystems.locomotion;
    this.vision = subsystems.vision;
    this.communication = subsystems.communication;
    this.safety = subsystems.safety;
  }

  /** Connects, and learns the device's identity and capabilities; NOT_CONNECTED when it is not there. */
  async initialize(): Promise<void> {
    if (this.#ready) return;
    this.#nc ??= await resolveConnection(this.#options);
    const link = new DeviceLink(this.#nc.nc, {
      deviceId: this.#options.deviceId,
      clientId: this.#clientId,
      callTimeoutMs: this.#options.callTimeoutMs ?? 120_000,
      attemptTimeoutMs: this.#options.attemptTimeoutMs ?? 2000,
      offlineAfterMs: this.#options.offlineAfterMs ?? 3000,
    });
    link.listen('differentialState', (data) => {
      const state = DifferentialStateSchema.safeParse(this.#payload(data));
      if (state.success) this.#deviceLatch(state.data.emergency_stopped);
    });
    link.listen('capabilityAnnounce', (data) => {
      const announcement = CapabilityAnnouncementSchema.safeParse(this.#payload(data));
      if (announcement.success) this.#learn(announcement.data);
    });
    try {
      const announcement = await link.request(
        'capabilityReq',
        SCHEMAS.capabilities,
        {},
        CapabilityAnnouncementSchema,
        { timeoutMs: Math.min(this.#options.callTimeoutMs ?? 5000, 5000) },
      );
      this.#learn(announcement, link.sender);
    } catch (error) {
      link.close();
      throw error instanceof HalError && error.code === 'TIMEOUT'
        ? new HalError('NOT_CONNECTED', 'no device answered the capability query', { cause: error })
        : error;
    }
    // an e-stop latched while we were not connected: the device latches too before we are ready
    const latch = this.#hostLatch;
    if (latch !== undefined) {
      try {
        await this.#deliverEstop(link, latch, Math.min(this.#options.callTimeoutMs ?? 5000, 5000));
      } catch (error) {
        link.close();
        throw error instanceof HalError && error.code !== 'TIMEOUT'
          ? error
          : new HalError(
              'NOT_CONNECTED',
              'the device did not take the e-stop latched before initialize()',
              {
                cause: error,
              },
            );
      }
    }
    this.#link = link;
    this.#ready = true;
    const beat = encodeMessage(SCHEMAS.heartbeat, this.#clientId, [], {});
    const subject = subjectFor('heartbeat', this.#options.deviceId);
    this.#heartbeat = setInterval(() => {
      if (!link.nc.isClosed()) link.nc.publish(subject, beat);
    }, this.#options.heartbeatMs ?? 1000);
    this.#heartbeat.unref();
  }

  /** Stops the device's wheels (best effort) and lets go of NATS. Safe to call twice. */
  async cleanup(): Promise<void> {
    const link = this.#link;
    if (!this.#ready || link === undefined) return;
    // Bounded: a device that is gone must not hold up cleanup for the whole call timeout.
    await this.#result('locomotion.stop', [], STOP_ON_CLEANUP_MS);
    this.#ready = false;
    this.#link = undefined;
    clearInterval(this.#heartbeat);
    link.close();
    if (this.#nc?.owned === true) await this.#nc.nc.close();
    this.#nc = undefined;
  }

  isReady(): boolean {
    return this.#ready && this.#link?.offline() === false;
  }

  getDeviceInfo(): DeviceInfo {
    return { ...this.#info, capabilities: [...this.#info.capabilities] };
  }

  #payload(data: Uint8Array): unknown {
    try {
      return decodeMessage(data, CapabilityAnnouncementSchema.or(DifferentialStateSchema)).payload;
    } catch {
      return undefined;
    }
  }

  /** What the device said about itself; `sender` (the reply's `device_id`) names the default one. */
  #learn(announcement: CapabilityAnnouncement, sender?: string): void {
    this.mode = announcement.mode as HALMode;
    this.#info = {
      id: this.#options.deviceId ?? sender ?? this.#info.id,
      type: announcement.device_type,
      mode: this.mode,
      capabilities: announcement.caps,
    };
  }

  #isEstopped(): boolean {
    return this.#deviceEstopped || this.#hostLatch !== undefined;
  }

  #safetyStatus(): SafetyStatus {
    const status: SafetyStatus = { ...this.#safety, emergencyStopped: this.#isEstopped() };
    const reason = this.#deviceReason ?? this.#hostLatch;
    if (status.emergencyStopped && reason !== undefined) status.emergencyStopReason = reason;
    return status;
  }

  /** The device's latch as a reply or its state reports it. */
  #deviceLatch(estopped: boolean, reason?: string): void {
    this.#deviceEstopped = estopped;
    if (!estopped) this.#deviceReason = undefined;
    else if (reason !== undefined) this.#deviceReason = reason;
  }

  async #emergencyStop(reason: unknown): Promise<HALToolResult> {
    const started = Date.now();
    const stored = sanitizeEstopReason(reason);
    this.#hostLatch = stored; // refuse motion at once, whatever the link does
    const link = this.#link;
    if (!this.#ready || link === undefined) {
      // not connected: initialize() sends it to the device before it reports ready
      const data = { estop: true, reason: stored, delivered: false };
      return successResult(this.mode, Date.now(), data, Date.now() - started);
    }
    try {
      const result = await this.#deliverEstop(link, stored);
      const data = { ...result.data, reason: this.#deviceReason ?? stored, delivered: true };
      return { ...result, data };
    } catch (error) {
      return failureResult(this.mode, Date.now(), error, Date.now() - started);
    }
  }

  /** Sends an e-stop with priority; throws unless the device took it. */
  async #deliverEstop(link: DeviceLink, reason: string, timeoutMs?: number) {
    const reply = await this.#request(link, 'safety.emergencyStop', [reason], timeoutMs);
    const result = HALToolResultSchema.safeParse(reply.result);
    if (!result.success) throw new HalError('MALFORMED', 'safety.emergencyStop: no result');
    if (!result.data.success) throw failureError(result.data as HALToolResult);
    const stored = result.data.data?.['reason'];
    this.#deviceReason = typeof stored === 'string' ? stored : reason;
    return result.data as HALToolResult;
  }

  async #resetEmergencyStop(): Promise<HALToolResult> {
    const result = await this.#result('safety.resetEmergencyStop', []);
    if (result.success) {
      this.#hostLatch = undefined;
    }
    return result;
  }

  async #call(call: string, args: unknown[], timeoutMs?: number) {
    const link = this.#link;
    if (!this.#ready || link === undefined) {
      throw new HalError('NOT_READY', `${call}: the HAL is not initialised (call initialize())`);
    }
    if (this.#motion.has(call) && this.#hostLatch !== undefined) {
      throw new HalError(
        'EMERGENCY_STOPPED',
        `${call}: the emergency stop is latched; call safety.resetEmergencyStop() first`,
      );
    }
    return this.#request(link, call, args, timeoutMs);
  }

  async #request(link: DeviceLink, call: string, args: unknown[], timeoutMs?: number) {
    const reply = await link.request(
      'call',
      SCHEMAS.call,
      { request_id: `${this.#clientId}-${(sequence += 1)}`, call, args: encodeArgs(args) },
      HalCallReplySchema,
      {
        priority: this.#safetyLane.has(call),
        ...(timeoutMs === undefined ? {} : { timeoutMs }),
      },
    );
    this.#deviceLatch(reply.emergency_stopped, reply.emergency_stop_reason);
    if (reply.error !== undefined) throw errorFromPayload(reply.error);
    return reply;
  }

  async #result(call: string, args: unknown[], timeoutMs?: number): Promise<HALToolResult> {
    const started = Date.now();
    try {
      const reply = await this.#call(call, args, timeoutMs);
      const result = HALToolResultSchema.safeParse(reply.result);
      if (!result.success) throw new HalError('MALFORMED', `${call}: the device sent no result`);
      return result.data as HALToolResult;
    } catch (error) {
      return failureResult(this.mode, Date.now(), error, Date.now() - started);
    }
  }

  async #value(call: string, args: unknown[]): Promise<unknown> {
    const reply = await this.#call(call, args);
    return reply.value;
  }

  #sendLog(message: string, level: HALLogLevel | undefined): void {
    try {
      const link = this.#link;
      if (!this.#ready || link === undefined) {
        this.#log.warn('log refused: the HAL is not initialised');
        return;
      }
      const data = encodeMessage(SCHEMAS.call, this.#clientId, [], { message, level });
      link.nc.publish(subjectFor('log', this.#options.deviceId), data);
    } catch (error) {
      this.#log.warn('log not sent', { error: String(error) });
    }
  }
}

/** The error a failed result reports, as a HalError. */
function failureError(result: HALToolResult): HalError {
  return new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? 'the call failed', {
    ...(result.details === undefined ? {} : { details: result.details }),
  });
}
