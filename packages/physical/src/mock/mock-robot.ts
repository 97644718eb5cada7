import { NOTHING_TO_TOUCH, RobotModel } from '@hal/kinematics';
import { isHalError, robotConfig } from '@hal/types';
import type { RobotConfig } from '@hal/types';
import type { MessageAuthenticator } from '../protocol/auth.js';
import type { TransportFactory } from '../transport/transport.js';
import { executeCommand, helloData } from './command-handlers.js';
import { mockTransport } from './mock-transport.js';
import type { MockTransportOptions } from './mock-transport.js';
import { Refusal } from './refusal.js';
import type { Json } from './refusal.js';
import { RobotClock } from './robot-clock.js';
import type { RobotState } from './robot-state.js';
import { SessionMemory } from './session-memory.js';
import { envelopeOf, MockWire, NO_ENVELOPE } from './wire.js';

/** Options of {@link MockRobot}. */
export interface MockRobotOptions {
  /** Reported by `hello`. Default `cube-mock`. */
  deviceId?: string;
  /** How much faster than real time the robot's clock runs. Default 1. */
  timeScale?: number;
  /** Real clock, ms. Default `performance.now`. */
  now?: () => number;
  /** Host timeout, ms. Default 2000. */
  hostTimeoutMs?: number;
  /**
   * Authenticate messages with this key (see `createAuthenticator`): every message MACed, every
   * request in a session. Without it the robot runs as the firmware's unauthenticated opt-out
   * (`CUBE_ALLOW_UNAUTHENTICATED`, the emulator on loopback): `hello` says `auth: "none"` and
   * requests without a session (seed-style) are accepted.
   */
  auth?: MessageAuthenticator;
}

/**
 * A fast, in-process robot that speaks protocol 1.1, for unit tests and for trying the library
 * without hardware. It is the wire and the session (messages and MACs, sessions and `hello`,
 * exactly-once retries, the replies' fields) around `@hal/kinematics`' RobotModel, the
 * simulator's model of the firmware's rules (step-exact motion from the firmware's planner,
 * odometry, e-stop, step limit, host timeout, set_config ranges): it keeps no rule of its own.
 * Each instance is its own robot: there is no shared state.
 * Test helpers: `requests` (every request received), `dropReplies(n)`, `unresponsive`,
 * `restart()`.
 */
export class MockRobot {
  readonly deviceId: string;
  /** Every request received, decoded, in order. */
  readonly requests: Json[] = [];
  /** When true the robot receives and executes nothing and answers nothing (a dead link). */
  unresponsive = false;
  /** Motions started (each executed command counts once, whatever the retries). */
  motionsStarted = 0;

  readonly #wire: MockWire;
  readonly #session = new SessionMemory();
  readonly #state: RobotState;
  #dropReplies = 0;
  #dropRequests = 0;

  constructor(options: MockRobotOptions = {}) {
    this.deviceId = options.deviceId ?? 'cube-mock';
    this.#wire = new MockWire(options.auth);
    const clock = new RobotClock(options.now ?? (() => performance.now()), options.timeScale ?? 1);
    const config = robotConfig({ hostTimeoutMs: options.hostTimeoutMs ?? 2000 });
    this.#state = { clock, model: poweredOn(config), led: { r: 0, g: 0, b: 0, pattern: 'off' } };
  }

  /** The robot model brought up to the robot's clock (finishing or timing out its motion). */
  #advance(): RobotModel {
    const { model, clock } = this.#state;
    model.advanceTo(clock.us());
    return model;
  }

  /** The absolute wheel positions, steps. */
  get position(): { left: number; right: number } {
    const model = this.#advance();
    return { left: model.leftSteps, right: model.rightSteps };
  }

  /** The last request received, decoded (undefined before the first). */
  get lastRequest(): Json | undefined {
    return this.requests[this.requests.length - 1];
  }

  /** Whether the emergency stop is latched. */
  get estopped(): boolean {
    return this.#state.model.emergencyStopped;
  }

  /** Drops the next `count` requests before they reach the robot (lost requests). */
  dropRequests(count: number): void {
    this.#dropRequests += count;
  }

  /** Drops the next `count` replies after executing their requests (lost replies). */
  dropReplies(count: number): void {
    this.#dropReplies += count;
  }

  /**
   * A power cycle: uptime, counters, motion, session, e-stop and the record of trips start over
   * (the configuration is kept).
   */
  restart(): void {
    const state = this.#state;
    state.clock.reboot();
    this.#session.forget();
    state.model = poweredOn(state.model.config);
  }

  /** A transport that talks to this robot in-process (through the real codec). */
  transport(options: MockTransportOptions = {}): TransportFactory<'mock'> {
    return mockTransport((bytes) => this.receive(bytes), options);
  }

  /**
   * Receives one message as the robot would from the link; returns the reply bytes, or
   * undefined when the reply is lost (`dropReplies`, `unresponsive`).
   */
  receive(bytes: Uint8Array): Uint8Array | undefined {
    if (this.unresponsive) return undefined;
    if (this.#dropRequests > 0) {
      this.#dropRequests -= 1;
      return undefined;
    }
    const reply = this.handle(bytes);
    if (this.#dropReplies > 0) {
      this.#dropReplies -= 1;
      return undefined;
    }
    return reply;
  }

  /** Handles one request and returns the reply bytes (the protocol logic, no losses). */
  handle(bytes: Uint8Array): Uint8Array {
    const model = this.#advance();
    const request = this.#wire.read(bytes);
    if (request instanceof Refusal) return this.#wire.error(NO_ENVELOPE, request);
    this.requests.push(request);
    const envelope = envelopeOf(request);
    if (envelope.cmd === 'hello') {
      model.touchHost();
      return this.#hello(request, envelope.seq);
    }
    const admission = this.#session.admit(envelope, this.#wire.authenticated);
    if (admission.kind === 'refuse') return this.#wire.error(envelope, admission.refusal);
    if (admission.kind === 'overtaken') {
      model.touchHost();
      const refused = this.#wire.error(envelope, admission.refusal);
      this.#session.remember(envelope.seq!, refused);
      return refused;
    }
    if (admission.kind === 'replay') {
      model.touchHost();
      return admission.reply;
    }
    if (admission.contact) model.touchHost();
    const { seq, sid, cmd } = envelope;
    const moveBefore = model.motion?.moveId;
    let reply: Uint8Array;
    try {
      reply = this.#wire.reply({
        seq,
        sid,
        ok: true,
        cmd,
        ...executeCommand(this.#state, cmd, request),
      });
    } catch (thrown) {
      reply = this.#wire.error(envelope, refusalOf(thrown));
    }
    if (model.motion?.moveId !== moveBefore) this.motionsStarted += 1;
    if (admission.remember) this.#session.remember(seq!, reply);
    return reply;
  }

  /** `hello`: a retry of the current session's keeps it; any other opens a new session. */
  #hello(request: Json, seq: number | undefined): Uint8Array {
    const nonce = typeof request['nonce'] === 'string' ? request['nonce'] : undefined;
    const retry = this.#session.helloRetry(nonce, seq);
    if (retry !== undefined) return retry;
    if (this.#wire.authenticated && (nonce === undefined || seq === undefined)) {
      return this.#wire.error(
        { cmd: 'hello', seq, sid: undefined },
        new Refusal('AUTH_FAILED', 'hello must carry seq and nonce'),
      );
    }
    const sid = this.#session.open(seq);
    this.#state.model.resetAccumulators();
    const reply: Json = { seq, sid, ok: true, cmd: 'hello' };
    if (nonce !== undefined) reply['nonce'] = nonce;
    const scheme = this.#wire.authenticated ? 'hmac-sha256' : 'none';
    Object.assign(reply, helloData(this.#state, this.deviceId, scheme));
    const bytes = this.#wire.reply(reply);
    this.#session.openedBy(nonce, seq, bytes);
    return bytes;
  }
}

/**
 * A robot just powered on: the firmware's rules over `config`, its host heard only at its
 * requests (a test's host sends no heartbeat the robot does not receive).
 */
function poweredOn(config: RobotConfig): RobotModel {
  const model = new RobotModel({ config });
  // nothing to touch, so no step needs a contact check: the steps are walked in bulk
  model.setContactTest(() => undefined, NOTHING_TO_TOUCH);
  model.setHostSilent(true);
  return model;
}

/** The error reply of a refused command: the wire's own refusal, or the robot model's HalError. */
function refusalOf(thrown: unknown): Refusal {
  if (thrown instanceof Refusal) return thrown;
  if (isHalError(thrown)) return new Refusal(thrown.code, thrown.message, thrown.details ?? {});
  throw thrown;
}
