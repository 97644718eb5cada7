import { ControllerWatch, ServedCalls } from '@hal/runtime';
import { HalError, V1_ROBOT, scoped, silentLogger } from '@hal/types';
import type { HardwareAbstractionLayer, RobotConfig, ScopedLogger } from '@hal/types';
import type { Msg, NatsConnection, Subscription } from '@nats-io/transport-node';
import { z } from 'zod';
import { decodeSpecMessage, encodeMessage } from './codec.js';
import { resolveConnection } from './connection.js';
import { CpuMeter } from './cpu-meter.js';
import { announcementOf } from './device-reports.js';
import { errorPayload } from './error-payload.js';
import { CallReplies } from './gateway-calls.js';
import { onCamera, onDrive, onEstop, onEstopReset, onHealth, onLog } from './gateway-handlers.js';
import type { GatewayOptions } from './gateway-options.js';
import type { GatewayPort } from './gateway-port.js';
import { StreamTicks } from './gateway-ticks.js';
import { natsCalls } from './hal-calls.js';
import { SCHEMAS } from './messages.js';
import type { CapabilityAnnouncement } from './messages.js';
import { refuseServedTwice } from './served-probe.js';
import { subjectFor } from './subjects.js';
import type { SubjectName } from './subjects.js';

/** A HAL served on NATS. The HAL stays the caller's: `close()` does not clean it up. */
export interface HalGateway {
  readonly deviceId: string;
  /** Stops serving (and closes the connection if the gateway opened it). */
  close(): Promise<void>;
}

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

/**
 * One device served: subscribes its subjects (the device's own, and the default ones for the
 * default device), hands each message to its handler, answers a failed one with the spec's error
 * body, and publishes the streams and the capability announcement.
 */
class Gateway implements HalGateway, GatewayPort {
  readonly deviceId: string;
  readonly served: ServedCalls;
  readonly started = Date.now();
  readonly robot: RobotConfig;
  readonly log: ScopedLogger;
  readonly controllers: ControllerWatch;
  readonly cpu = new CpuMeter();
  readonly #subs: Subscription[] = [];
  readonly #timers: NodeJS.Timeout[] = [];
  readonly #isDefault: boolean;
  readonly #calls: CallReplies;
  readonly #ticks = new StreamTicks(this);
  #closed = false;

  constructor(
    readonly nc: NatsConnection,
    readonly owned: boolean,
    readonly hal: HardwareAbstractionLayer,
    readonly options: GatewayOptions,
  ) {
    this.deviceId = options.deviceId;
    this.#isDefault = options.defaultDevice ?? true;
    this.robot = options.robot ?? V1_ROBOT;
    this.log = scoped(options.logger ?? silentLogger, 'hal:nats:gateway');
    this.#calls = new CallReplies(this, natsCalls(options.calls));
    subjectFor('call', this.deviceId); // refuses a bad device id before anything is served
    this.served = new ServedCalls(hal, { calls: options.calls, order: 'ordered' });
    this.controllers = new ControllerWatch(hal, {
      timeoutMs: options.controllerTimeoutMs ?? 3000,
      log: this.log,
      onSilent: (client, silentMs) =>
        void this.controllers.stopFor(
          client,
          `went silent for ${silentMs} ms during an open-ended drive`,
        ),
    });
  }

  get closed(): boolean {
    return this.#closed;
  }

  /** Subscribes every subject, and starts the state stream and the announcements. */
  start(): void {
    this.#serve('call', (m) => this.#calls.onCall(m));
    this.#serve('differentialCmd', (m) => onDrive(this, m));
    this.#serve('estop', (m) => onEstop(this, m));
    this.#serve('estopReset', (m) => onEstopReset(this, m));
    this.#serve('health', (m) => onHealth(this, m));
    this.#serve('capabilityReq', (m) => this.reply(m, SCHEMAS.capabilities, this.#announcement()));
    this.#serve('cameraFrame', (m) => onCamera(this, m));
    this.#serve('log', (m) => onLog(this, m));
    this.#serve('heartbeat', async (m) => {
      this.controllers.heard(decodeSpecMessage(m.data, z.looseObject({})).device_id);
    });
    const rate = this.options.stateRateHz ?? 20;
    if (rate !== 0 && !(rate >= 10 && rate <= 100)) {
      throw new HalError('RANGE_EXCEEDED', `"stateRateHz" must be 0 or 10..100, got ${rate}`);
    }
    if (rate > 0) this.#timers.push(setInterval(() => void this.#ticks.tick(), 1000 / rate));
    this.publish('capabilityAnnounce', SCHEMAS.capabilities, this.#announcement());
    this.#timers.push(
      setInterval(
        () => this.publish('capabilityAnnounce', SCHEMAS.capabilities, this.#announcement()),
        this.options.announceIntervalMs ?? 5000,
      ),
    );
  }

  async close(): Promise<void> {
    if (this.#closed) return;
    this.#closed = true;
    this.controllers.close();
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
              this.log.warn('subscription failed', { subject, error: error.message });
              return;
            }
            handler(msg).catch((thrown: unknown) => this.#fail(msg, thrown));
          },
        }),
      );
    }
  }

  encode(schema: string, payload: unknown): Uint8Array {
    return encodeMessage(schema, this.deviceId, this.hal.getDeviceInfo().capabilities, payload);
  }

  publish(name: SubjectName, schema: string, payload: unknown): void {
    if (this.#closed || this.nc.isClosed()) return;
    const data = this.encode(schema, payload);
    this.nc.publish(subjectFor(name, this.deviceId), data);
    if (this.#isDefault) this.nc.publish(subjectFor(name), data);
  }

  async reply(msg: Msg, schema: string, payload: unknown): Promise<void> {
    if (msg.reply !== undefined && msg.reply !== '') msg.respond(this.encode(schema, payload));
  }

  /** Answers a failed message with the spec's error body, or logs it when nobody asked. */
  #fail(msg: Msg, thrown: unknown): void {
    const error = errorPayload(thrown);
    this.log.debug('message refused', { subject: msg.subject, code: error.code });
    void this.reply(msg, SCHEMAS.error, { error });
  }

  #announcement(): CapabilityAnnouncement {
    return announcementOf(this.hal, this.options.stateRateHz ?? 20);
  }
}
