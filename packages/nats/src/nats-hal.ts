import { HalError, HALToolResultSchema, failureResult } from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALLogLevel,
  HALMode,
  HALToolResult,
  HardwareAbstractionLayer,
  IMUReading,
  LocomotionInterface,
  Pose,
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
import type { NatsLogger } from './logger.js';
import { silentNatsLogger } from './logger.js';
import {
  CapabilityAnnouncementSchema,
  DifferentialStateSchema,
  HalCallReplySchema,
  SCHEMAS,
} from './messages.js';
import type { CapabilityAnnouncement } from './messages.js';
import { subjectFor } from './subjects.js';

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
  logger?: NatsLogger;
};

let sequence = 0;
const STOP_ON_CLEANUP_MS = 2000;

/**
 * A {@link HardwareAbstractionLayer} that drives a device through NATS: every call goes to the
 * device's gateway (`serveHalOnNats`) and comes back with the device's own result. The same
 * agent code drives a robot on the desk or one across a building. A device that goes silent is
 * offline: its calls fail NOT_CONNECTED; nothing waits longer than `callTimeoutMs`.
 */
export class NatsHAL implements HardwareAbstractionLayer {
  mode: HALMode = 'simulation';
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  readonly #options: NatsHALOptions;
  readonly #clientId: string;
  readonly #log: NatsLogger;
  #link: DeviceLink | undefined;
  #nc: { nc: NatsConnection; owned: boolean } | undefined;
  #ready = false;
  #heartbeat: NodeJS.Timeout | undefined;
  #info: DeviceInfo;
  #estopped = false;
  #safety: SafetyStatus = { emergencyStopped: false, batteryLevel: 100, errors: [] };

  constructor(options: NatsHALOptions) {
    this.#options = options;
    this.#clientId = options.clientId ?? `nats-hal-${process.pid}-${(sequence += 1)}`;
    this.#log = options.logger ?? silentNatsLogger;
    if (options.deviceId !== undefined) subjectFor('call', options.deviceId); // checks the id
    this.#info = {
      id: options.deviceId ?? 'default',
      type: 'nats',
      mode: this.mode,
      capabilities: [],
    };
    const result =
      (call: string) =>
      (...args: unknown[]) =>
        this.#result(call, args);
    const value =
      <T>(call: string) =>
      (...args: unknown[]) =>
        this.#value<T>(call, args);
    this.locomotion = {
      drive: result('locomotion.drive'),
      moveTo: result('locomotion.moveTo'),
      rotate: result('locomotion.rotate'),
      moveForward: result('locomotion.moveForward'),
      moveBackward: result('locomotion.moveBackward'),
      stop: result('locomotion.stop'),
      getPose: value<Pose>('locomotion.getPose'),
    };
    this.vision = {
      captureFrame: value<string>('vision.captureFrame'),
      scan: value('vision.scan'),
      getDistanceSensors: value('vision.getDistanceSensors'),
      getLineSensors: value<number[]>('vision.getLineSensors'),
      getIMU: value<IMUReading>('vision.getIMU'),
    };
    this.communication = {
      speak: result('communication.speak'),
      setLED: result('communication.setLED'),
      playSound: result('communication.playSound'),
      log: (message: string, level?: HALLogLevel) => this.#sendLog(message, level),
    };
    this.safety = {
      emergencyStop: result('safety.emergencyStop'),
      resetEmergencyStop: result('safety.resetEmergencyStop'),
      isEmergencyStopped: () => this.#estopped,
      getSafetyStatus: () => ({ ...this.#safety, emergencyStopped: this.#estopped }),
    };
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
      if (state.success) this.#estopped = state.data.emergency_stopped;
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
      this.#learn(announcement);
    } catch (error) {
      link.close();
      throw error instanceof HalError && error.code === 'TIMEOUT'
        ? new HalError('NOT_CONNECTED', 'no device answered the capability query', { cause: error })
        : error;
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

  #learn(announcement: CapabilityAnnouncement): void {
    this.mode = announcement.mode as HALMode;
    this.#info = {
      id: this.#options.deviceId ?? this.#info.id,
      type: announcement.device_type,
      mode: this.mode,
      capabilities: announcement.caps,
    };
  }

  async #call(call: string, args: unknown[], timeoutMs?: number) {
    const link = this.#link;
    if (!this.#ready || link === undefined) {
      throw new HalError('NOT_READY', `${call}: the HAL is not initialised (call initialize())`);
    }
    const reply = await link.request(
      'call',
      SCHEMAS.call,
      { request_id: `${this.#clientId}-${(sequence += 1)}`, call, args: encodeArgs(args) },
      HalCallReplySchema,
      {
        priority: call === 'safety.emergencyStop' || call === 'locomotion.stop',
        ...(timeoutMs === undefined ? {} : { timeoutMs }),
      },
    );
    this.#estopped = reply.emergency_stopped;
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

  async #value<T>(call: string, args: unknown[]): Promise<T> {
    const reply = await this.#call(call, args);
    return reply.value as T;
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
