import { ForwardingHAL } from '@hal/runtime';
import type { SendOptions } from '@hal/runtime';
import { HalError, scoped, silentLogger } from '@hal/types';
import type {
  CallSpec,
  CallTable,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  Logger,
  SafetyStatus,
  ScopedLogger,
} from '@hal/types';
import type { NatsConnection } from '@nats-io/transport-node';
import { decodeMessage, encodeArgs, encodeMessage } from './codec.js';
import type { NatsConnectionSource } from './connection.js';
import { resolveConnection } from './connection.js';
import { DeviceLink, errorFromPayload } from './device-link.js';
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
/**
 * A {@link HardwareAbstractionLayer} that drives a device through NATS: every call goes to the
 * device's gateway (`serveHalOnNats`) and comes back with the device's own result. The same
 * agent code drives a robot on the desk or one across a building. A device that goes silent is
 * offline: its calls fail NOT_CONNECTED; nothing waits longer than `callTimeoutMs`.
 *
 * The latch, readiness, e-stop delivery and cleanup are {@link ForwardingHAL}'s: the e-stop
 * latches on this host at once and is held here until an accepted reset (`until-reset`).
 */
export class NatsHAL extends ForwardingHAL {
  readonly #options: NatsHALOptions;
  readonly #clientId: string;
  readonly #log: ScopedLogger;
  #mode: HALMode = 'simulation';
  #link: DeviceLink | undefined;
  #nc: { nc: NatsConnection; owned: boolean } | undefined;
  #heartbeat: NodeJS.Timeout | undefined;
  #info: DeviceInfo;
  /** The device's own latch, as its last reply or state said. */
  #deviceEstopped = false;
  /** The reason the device stored, as its last reply said. */
  #deviceReason: string | undefined;

  constructor(options: NatsHALOptions) {
    const log = scoped(options.logger ?? silentLogger, 'hal:nats:hal');
    super({ calls: options.calls, latch: 'until-reset', log });
    this.#options = options;
    this.#log = log;
    this.#clientId = options.clientId ?? `nats-hal-${process.pid}-${(sequence += 1)}`;
    if (options.deviceId !== undefined) subjectFor('call', options.deviceId); // checks the id
    this.#info = {
      id: options.deviceId ?? 'default',
      type: 'nats',
      mode: 'simulation',
      capabilities: [],
    };
  }

  /** The device's mode, learned on connecting. */
  get mode(): HALMode {
    return this.#mode;
  }

  getDeviceInfo(): DeviceInfo {
    return { ...this.#info, capabilities: [...this.#info.capabilities] };
  }

  /** Connects, and learns the device's identity and capabilities; NOT_CONNECTED when it is not there. */
  protected async open(): Promise<void> {
    this.#link?.close();
    this.#nc ??= await resolveConnection(this.#options);
    const link = new DeviceLink(this.#nc.nc, {
      deviceId: this.#options.deviceId,
      clientId: this.#clientId,
      callTimeoutMs: this.#options.callTimeoutMs ?? 120_000,
      attemptTimeoutMs: this.#options.attemptTimeoutMs ?? 2000,
      offlineAfterMs: this.#options.offlineAfterMs ?? 3000,
    });
    this.#link = link;
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
      throw error instanceof HalError && error.code === 'TIMEOUT'
        ? new HalError('NOT_CONNECTED', 'no device answered the capability query', { cause: error })
        : error;
    }
    const beat = encodeMessage(SCHEMAS.heartbeat, this.#clientId, [], {});
    const subject = subjectFor('heartbeat', this.#options.deviceId);
    clearInterval(this.#heartbeat);
    this.#heartbeat = setInterval(() => {
      if (!link.nc.isClosed()) link.nc.publish(subject, beat);
    }, this.#options.heartbeatMs ?? 1000);
    this.#heartbeat.unref();
  }

  protected async close(): Promise<void> {
    clearInterval(this.#heartbeat);
    this.#link?.close();
    this.#link = undefined;
    const nc = this.#nc;
    this.#nc = undefined;
    if (nc?.owned === true) await nc.nc.close();
  }

  protected reachable(): boolean {
    return this.#link?.offline() === false;
  }

  protected servedSafety(): Partial<SafetyStatus> {
    const status: Partial<SafetyStatus> = { emergencyStopped: this.#deviceEstopped };
    if (this.#deviceEstopped && this.#deviceReason !== undefined) {
      status.emergencyStopReason = this.#deviceReason;
    }
    return status;
  }

  protected async send(
    spec: CallSpec,
    args: unknown[],
    options: SendOptions = {},
  ): Promise<unknown> {
    const call = natsCallName(spec);
    if (!crossesNats(spec)) throw new HalError('NOT_IMPLEMENTED', `${call} does not cross NATS`);
    const link = this.#link;
    if (link === undefined) {
      throw new HalError('NOT_READY', `${call}: the HAL is not initialised (call initialize())`);
    }
    const own = this.#options.callTimeoutMs ?? 120_000;
    const reply = await link.request(
      'call',
      SCHEMAS.call,
      { request_id: `${this.#clientId}-${(sequence += 1)}`, call, args: encodeArgs(args) },
      HalCallReplySchema,
      { priority: spec.lane === 'safety', timeoutMs: Math.min(own, options.timeoutMs ?? own) },
    );
    this.#deviceLatch(reply.emergency_stopped, reply.emergency_stop_reason);
    if (reply.error !== undefined) throw errorFromPayload(reply.error);
    return spec.kind === 'value' ? reply.value : reply.result;
  }

  protected sendLog(message: string, level: HALLogLevel | undefined): void {
    try {
      const link = this.#link;
      if (link === undefined) throw new HalError('NOT_READY', 'no link to the device');
      const data = encodeMessage(SCHEMAS.call, this.#clientId, [], { message, level });
      link.nc.publish(subjectFor('log', this.#options.deviceId), data);
    } catch (error) {
      this.#log.warn('log not sent', { error: String(error) });
    }
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
    this.#mode = announcement.mode as HALMode;
    this.#info = {
      id: this.#options.deviceId ?? sender ?? this.#info.id,
      type: announcement.device_type,
      mode: this.#mode,
      capabilities: announcement.caps,
    };
  }

  /** The device's latch as a reply or its state reports it. */
  #deviceLatch(estopped: boolean, reason?: string): void {
    this.#deviceEstopped = estopped;
    if (!estopped) this.#deviceReason = undefined;
    else if (reason !== undefined) this.#deviceReason = reason;
  }
}
