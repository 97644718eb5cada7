import {
  ControllerWatch,
  HalError,
  ServedCalls,
  V1_ROBOT,
  findCall,
  sanitizeEstopReason,
  scoped,
  silentLogger,
  toHalError,
} from '@hal/types';
import type {
  CallSpec,
  HALToolResult,
  HardwareAbstractionLayer,
  RobotConfig,
  ScopedLogger,
} from '@hal/types';
import type { Msg, NatsConnection, Subscription } from '@nats-io/transport-node';
import { announcementOf, cameraFrameOf, healthOf } from './device-reports.js';
import { errorPayload } from './error-payload.js';
import type { GatewayOptions } from './gateway-options.js';
import { decodeArgs, decodeMessage, decodeSpecMessage, encodeMessage } from './codec.js';
import { CpuMeter } from './cpu-meter.js';
import { resolveConnection } from './connection.js';
import { refuseServedTwice } from './served-probe.js';
import { wheelPowersFor } from './drive-mapping.js';
import { offersStream, readDifferentialState, readImu, readRange } from './gateway-streams.js';
import type { OfferedStreams } from './gateway-streams.js';
import { natsCalls } from './hal-calls.js';
import type { NatsCall } from './hal-calls.js';
import {
  CameraFrameRequestSchema,
  DifferentialCommandSchema,
  HalCallSchema,
  HealthRequestSchema,
  SCHEMAS,
} from './messages.js';
import type { CapabilityAnnouncement, HalCallReply } from './messages.js';
import { subjectFor } from './subjects.js';
import type { SubjectName } from './subjects.js';
import { z } from 'zod';

/** A HAL served on NATS. The HAL stays the caller's: `close()` does not clean it up. */
export interface HalGateway {
  readonly deviceId: string;
  /** Stops serving (and closes the connection if the gateway opened it). */
  close(): Promise<void>;
}

const DEDUP_ENTRIES = 1024;

/**
 * Serves `hal` on NATS: the spec's subjects (differential drive, state, IMU and range streams,
 * camera frames, health, capabilities, e-stop) and `hal.call.req`, the whole HAL contract for
 * {@link NatsHAL}. Commands run one at a time; stop, e-stop and anything sent with the header
 * `Priority: high` run at once, ahead of the queue. A call repeated with the same `request_id`
 * (a client retrying after a reconnect) is answered from the first execution, never run twice.
 */
export async function serveHalOnNats(
  hal: HardwareAbstractionLayer,
  options: GatewayOptions,
): Promise<HalGateway> {
  const { nc, owned } = await resolveConnection(options);
  try {
    await refuseServedTwice(nc, {
      deviceId: options.deviceId,
      defaultDevice: options.defaultDevice ?? true,
    });
  } catch (error) {
    if (owned) await nc.close();
    throw error;
  }
  const gateway = new Gateway(nc, owned, hal, options);
  gateway.start();
  await nc.flush(); // the server has every subscription: the first request finds a responder
  return gateway;
}

class Gateway implements HalGateway {
  readonly deviceId: string;
  readonly #served: ServedCalls;
  readonly #subs: Subscription[] = [];
  readonly #timers: NodeJS.Timeout[] = [];
  readonly #replies = new Map<string, Promise<Uint8Array>>();
  readonly #started = Date.now();
  readonly #isDefault: boolean;
  readonly #robot: RobotConfig;
  readonly #log: ScopedLogger;
  /** The controller of an open-ended drive, whose silence stops it. */
  readonly #controllers: ControllerWatch;
  readonly #cpu = new CpuMeter();
  readonly #calls: Readonly<Record<string, NatsCall>>;
  #streaming = false;
  #offered: OfferedStreams | undefined;
  #offeredFor = '';
  #closed = false;

  constructor(
    readonly nc: NatsConnection,
    readonly owned: boolean,
    readonly hal: HardwareAbstractionLayer,
    readonly options: GatewayOptions,
  ) {
    this.deviceId = options.deviceId;
    this.#isDefault = options.defaultDevice ?? true;
    this.#robot = options.robot ?? V1_ROBOT;
    this.#log = scoped(options.logger ?? silentLogger, 'hal:nats:gateway');
    this.#calls = natsCalls(options.calls);
    subjectFor('call', this.deviceId); // refuses a bad device id before anything is served
    this.#served = new ServedCalls(hal, { calls: options.calls, order: 'ordered' });
    this.#controllers = new ControllerWatch(hal, {
      timeoutMs: options.controllerTimeoutMs ?? 3000,
      log: this.#log,
      onSilent: (client, silentMs) =>
        void this.#controllers.stopFor(
          client,
          `went silent for ${silentMs} ms during an open-ended drive`,
        ),
    });
  }

  start(): void {
    this.#serve('call', (m) => this.#onCall(m));
    this.#serve('differentialCmd', (m) => this.#onDrive(m));
    this.#serve('estop', (m) => this.#onEstop(m));
    this.#serve('estopReset', (m) => this.#onEstopReset(m));
    this.#serve('health', (m) => this.#onHealth(m));
    this.#serve('capabilityReq', (m) => this.#reply(m, SCHEMAS.capabilities, this.#announcement()));
    this.#serve('cameraFrame', (m) => this.#onCamera(m));
    this.#serve('log', (m) => this.#onLog(m));
    this.#serve('heartbeat', async (m) => {
      this.#controllers.heard(decodeSpecMessage(m.data, z.looseObject({})).device_id);
    });
    const rate = this.options.stateRateHz ?? 20;
    if (rate !== 0 && !(rate >= 10 && rate <= 100)) {
      throw new HalError('RANGE_EXCEEDED', `"stateRateHz" must be 0 or 10..100, got ${rate}`);
    }
    if (rate > 0) this.#timers.push(setInterval(() => void this.#stream(), 1000 / rate));
    this.#publish('capabilityAnnounce', SCHEMAS.capabilities, this.#announcement());
    this.#timers.push(
      setInterval(
        () => this.#publish('capabilityAnnounce', SCHEMAS.capabilities, this.#announcement()),
        this.options.announceIntervalMs ?? 5000,
      ),
    );
  }

  async close(): Promise<void> {
    if (this.#closed) return;
    this.#closed = true;
    this.#controllers.close();
    for (const timer of this.#timers) clearInterval(timer);
    for (const sub of this.#subs) sub.unsubscribe();
    if (this.owned) await this.nc.close();
  }

  #serve(name: SubjectName, handler: (msg: Msg) => Promise<void>): void {
    const subjects = [subjectFor(name, this.deviceId)];
    if (this.#isDefault) subjects.push(subjectFor(name));
    for (const subject of subjects) {
      this.#subs.push(
        this.nc.subscribe(subject, {
          callback: (error, msg) => {
            if (error !== null) {
              this.#log.warn('subscription failed', { subject, error: error.message });
              return;
            }
            handler(msg).catch((thrown: unknown) => this.#fail(msg, thrown));
          },
        }),
      );
    }
  }

  #caps(): string[] {
    return this.hal.getDeviceInfo().capabilities;
  }

  #encode(schema: string, payload: unknown): Uint8Array {
    return encodeMessage(schema, this.deviceId, this.#caps(), payload);
  }

  #publish(name: SubjectName, schema: string, payload: unknown): void {
    if (this.#closed || this.nc.isClosed()) return;
    const data = this.#encode(schema, payload);
    this.nc.publish(subjectFor(name, this.deviceId), data);
    if (this.#isDefault) this.nc.publish(subjectFor(name), data);
  }

  async #reply(msg: Msg, schema: string, payload: unknown): Promise<void> {
    if (msg.reply !== undefined && msg.reply !== '') msg.respond(this.#encode(schema, payload));
  }

  /** Answers a failed message with the spec's error body, or logs it when nobody asked. */
  #fail(msg: Msg, thrown: unknown): void {
    const error = errorPayload(thrown);
    this.#log.debug('message refused', { subject: msg.subject, code: error.code });
    void this.#reply(msg, SCHEMAS.error, { error });
  }

  #priority(msg: Msg): boolean {
    return msg.headers?.get('Priority').toLowerCase() === 'high';
  }

  async #onCall(msg: Msg): Promise<void> {
    const envelope = decodeMessage(msg.data, HalCallSchema);
    const call = envelope.payload;
    const id = call.request_id;
    this.#controllers.heard(envelope.device_id);
    let reply = this.#replies.get(id);
    if (reply === undefined) {
      this.#watch(envelope.device_id, call.call, call.args.length < 3);
      reply = this.#execute(call.call, decodeArgs(call.args), this.#priority(msg)).then((body) =>
        this.#encode(SCHEMAS.callReply, { request_id: id, ...body }),
      );
      this.#replies.set(id, reply);
      if (this.#replies.size > DEDUP_ENTRIES) {
        const oldest = this.#replies.keys().next().value;
        if (oldest !== undefined) this.#replies.delete(oldest);
      }
    }
    const data = await reply;
    if (msg.reply !== undefined && msg.reply !== '') msg.respond(data);
  }

  async #execute(
    name: string,
    args: unknown[],
    priority: boolean,
  ): Promise<Omit<HalCallReply, 'request_id'>> {
    const spec = Object.hasOwn(this.#calls, name) ? this.#calls[name] : undefined;
    // every reply carries the latch, and its reason while latched, so a client's status has both
    const safety = () => {
      const emergency_stopped = this.hal.safety.isEmergencyStopped();
      const reason = emergency_stopped
        ? this.hal.safety.getSafetyStatus().emergencyStopReason
        : undefined;
      return reason === undefined
        ? { emergency_stopped }
        : { emergency_stopped, emergency_stop_reason: reason };
    };
    if (spec === undefined) {
      return {
        error: { code: 'UNKNOWN_COMMAND', message: `"call" is not a HAL call: "${name}"` },
        ...safety(),
      };
    }
    try {
      const out = await this.#served.run(spec.spec, args, { priority });
      return spec.kind === 'result' ? { result: out, ...safety() } : { value: out, ...safety() };
    } catch (thrown) {
      return { error: errorPayload(thrown), ...safety() };
    }
  }

  async #onDrive(msg: Msg): Promise<void> {
    const envelope = decodeSpecMessage(msg.data, DifferentialCommandSchema);
    const command = envelope.payload;
    this.#controllers.heard(envelope.device_id);
    const { left, right } = wheelPowersFor(command, this.#robot);
    const stop = left === 0 && right === 0 && command.duration_ms === undefined;
    this.#watch(
      envelope.device_id,
      stop ? 'locomotion.stop' : 'locomotion.drive',
      command.duration_ms === undefined,
    );
    const result = (await (stop
      ? this.#served.run(callSpec('stop'), [])
      : this.#served.run(callSpec('drive'), [left, right, command.duration_ms], {
          priority: this.#priority(msg),
        }))) as HALToolResult;
    if (!result.success) {
      throw new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? 'drive failed', {
        details: result.details ?? {},
      });
    }
    await this.#reply(msg, SCHEMAS.ack, { ok: true, left_power: left, right_power: right });
  }

  /** Keeps the watchdog on an open-ended drive, and off once any other motion or stop replaces it. */
  #watch(client: string, call: string, noDuration: boolean): void {
    if (call === 'locomotion.drive' && noDuration) {
      this.#controllers.forget(); // one open-ended drive at a time: the latest
      this.#controllers.watch(client);
    } else if (call.startsWith('locomotion.') && call !== 'locomotion.getPose') {
      this.#controllers.forget();
    } else if (call === 'safety.emergencyStop') this.#controllers.forget();
  }

  async #onEstop(msg: Msg): Promise<void> {
    // Never refused: any reason becomes a stored text (sanitizeEstopReason), and a message that
    // cannot be read at all (not JSON, another major version) still stops the robot, with a
    // reason that says so: whoever publishes on this subject wants the robot stopped.
    let reason: string | undefined;
    try {
      const body = decodeSpecMessage(msg.data, z.looseObject({ reason: z.unknown() })).payload;
      reason = body.reason === undefined ? undefined : sanitizeEstopReason(body.reason);
    } catch (error) {
      const unread = toHalError(error);
      reason = sanitizeEstopReason(`unreadable e-stop message (${unread.code})`);
      this.#log.warn('an unreadable e-stop message: stopping all the same', {
        code: unread.code,
        error: unread.message,
      });
    }
    const result = await this.hal.safety.emergencyStop(reason);
    await this.#reply(msg, SCHEMAS.ack, { ok: result.success, emergency_stopped: true });
  }

  async #onEstopReset(msg: Msg): Promise<void> {
    decodeSpecMessage(msg.data, z.looseObject({}));
    const result = await this.hal.safety.resetEmergencyStop();
    if (!result.success) throw new HalError(result.code ?? 'HARDWARE_ERROR', result.error ?? '');
    await this.#reply(msg, SCHEMAS.ack, { ok: true, emergency_stopped: false });
  }

  async #onHealth(msg: Msg): Promise<void> {
    const request = decodeSpecMessage(msg.data, HealthRequestSchema).payload;
    const health = healthOf(this.hal, {
      uptimeS: (Date.now() - this.#started) / 1000,
      cpuPercent: this.#cpu.percent(),
      includeDiagnostics: request.include_diagnostics === true,
    });
    await this.#reply(msg, SCHEMAS.health, health);
  }

  async #onCamera(msg: Msg): Promise<void> {
    decodeSpecMessage(msg.data, CameraFrameRequestSchema);
    await this.#reply(msg, SCHEMAS.cameraFrame, await cameraFrameOf(this.hal));
  }

  async #onLog(msg: Msg): Promise<void> {
    const body = decodeSpecMessage(
      msg.data,
      z.looseObject({ message: z.unknown(), level: z.unknown().optional() }),
    ).payload;
    this.hal.communication.log(body.message as string, body.level as 'info' | undefined);
  }

  #announcement(): CapabilityAnnouncement {
    return announcementOf(this.hal, this.options.stateRateHz ?? 20);
  }

  /**
   * The optional streams the device offers now: its capabilities are read at every tick (a robot
   * may gain a camera or a sensor), but parsed again only when they change.
   */
  #offeredStreams(): OfferedStreams {
    const capabilities = this.hal.getDeviceInfo().capabilities;
    const key = capabilities.join('\n');
    if (this.#offered === undefined || this.#offeredFor !== key) {
      this.#offered = offersStream(capabilities);
      this.#offeredFor = key;
    }
    return this.#offered;
  }

  /** One tick of the streams; a tick still reading when the next is due is not overlapped. */
  async #stream(): Promise<void> {
    if (this.#streaming || this.#closed || !this.hal.isReady()) return;
    this.#streaming = true;
    try {
      this.#publish(
        'differentialState',
        SCHEMAS.differentialState,
        await readDifferentialState(this.hal, this.#robot),
      );
      const offered = this.#offeredStreams();
      const imu = await readImu(this.hal, offered.imu);
      if (imu !== undefined) this.#publish('imuData', SCHEMAS.imu, imu);
      const range = await readRange(this.hal, offered.range);
      if (range !== undefined) {
        for (const sensor of range.perSensor) this.#publish('rangeData', SCHEMAS.range, sensor);
        this.#publish('rangeSummary', SCHEMAS.rangeSummary, range.summary);
      }
    } catch (thrown) {
      this.#log.debug('state read failed', { error: toHalError(thrown).message });
    } finally {
      this.#streaming = false;
    }
  }
}

/** A call of the HAL's own table (the spec's drive subject maps onto drive and stop). */
function callSpec(name: 'drive' | 'stop'): CallSpec {
  const spec = findCall(name);
  if (spec === undefined) throw new HalError('HARDWARE_ERROR', `the call table has no "${name}"`);
  return spec;
}
