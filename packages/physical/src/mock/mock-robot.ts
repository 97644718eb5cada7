import {
  MovePlan,
  OdometryIntegrator,
  rotationArcCm,
  StepAccumulator,
  VelocityPlan,
} from '@hal/kinematics';
import type { StepPlan } from '@hal/kinematics';
import { HalError } from '@hal/types';
import type { MessageAuthenticator } from '../protocol/auth.js';
import { MAC_SUFFIX_LENGTH } from '../protocol/auth.js';
import type { MoveOutcome } from '../protocol/schemas.js';
import type { RequestOptions, Transport, TransportFactory } from '../transport/transport.js';
import { ReplyMatcher } from '../transport/transport.js';

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
  /** Authenticate messages with this key (see `createAuthenticator`). */
  auth?: MessageAuthenticator;
}

/** Options of {@link MockRobot.transport}. */
export interface MockTransportOptions {
  /** Deliver each reply after this many ms. Default 0 (next macrotask). */
  latencyMs?: number;
  timeoutMs?: number;
  attempts?: number;
}

interface Motion {
  plan: StepPlan;
  startUs: number;
  /** Cap on the motion's length, robot µs (a drive with a duration). */
  endUs: number;
  baseLeft: number;
  baseRight: number;
  left: number;
  right: number;
}

type Json = Record<string, unknown>;

class Refusal extends Error {
  constructor(
    readonly code: string,
    message: string,
    readonly details: Json = {},
  ) {
    super(message);
  }
}

const MAX_STEPS = 40960;
const MEMORY = 16;
const encoder = new TextEncoder();
const decoder = new TextDecoder();

/**
 * A fast, in-process robot that speaks protocol 1.0 (sessions, exactly-once retries, step-exact
 * motion from the firmware's own planner, odometry, e-stop, host timeout), for unit tests and for
 * trying the library without hardware. Each instance is its own robot: there is no shared state.
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

  readonly #now: () => number;
  readonly #timeScale: number;
  readonly #auth: MessageAuthenticator | undefined;
  #bootAt: number;
  #config = {
    wheel_diameter_cm: 6,
    wheel_base_cm: 10,
    steps_per_revolution: 4096,
    max_speed_steps_per_s: 1024,
    acceleration_steps_per_s2: 512,
    host_timeout_ms: 2000,
  };
  #sid = 0;
  #helloKey = '';
  #helloReply: Uint8Array | undefined;
  #lastSeq = 0;
  #memory = new Map<number, Uint8Array>();
  #dropReplies = 0;
  #left = 0;
  #right = 0;
  #odometry = new OdometryIntegrator();
  #accLeft = new StepAccumulator();
  #accRight = new StepAccumulator();
  #motion: Motion | undefined;
  #moveId = 0;
  #outcome: MoveOutcome = 'none';
  #moveLeft = 0;
  #moveRight = 0;
  #lastHostUs = 0;
  #estop = false;
  #estopReason = '';
  #trips = 0;
  #lastTrip: Json | null = null;
  #led = { r: 0, g: 0, b: 0, pattern: 'off' };

  constructor(options: MockRobotOptions = {}) {
    this.deviceId = options.deviceId ?? 'cube-mock';
    this.#now = options.now ?? (() => performance.now());
    this.#timeScale = options.timeScale ?? 1;
    this.#auth = options.auth;
    this.#config.host_timeout_ms = options.hostTimeoutMs ?? 2000;
    this.#bootAt = this.#now();
    this.#resetGeometry();
  }

  /** The absolute wheel positions, steps. */
  get position(): { left: number; right: number } {
    this.#advance();
    return { left: this.#left, right: this.#right };
  }

  /** The last request received, decoded (undefined before the first). */
  get lastRequest(): Json | undefined {
    return this.requests[this.requests.length - 1];
  }

  /** Whether the emergency stop is latched. */
  get estopped(): boolean {
    return this.#estop;
  }

  /** Drops the next `count` replies after executing their requests (lost replies). */
  dropReplies(count: number): void {
    this.#dropReplies += count;
  }

  /** A power cycle: counters, session, e-stop and configuration start over. */
  restart(): void {
    this.#bootAt = this.#now();
    this.#sid = 0;
    this.#helloReply = undefined;
    this.#memory.clear();
    this.#left = 0;
    this.#right = 0;
    this.#motion = undefined;
    this.#moveId = 0;
    this.#outcome = 'none';
    this.#estop = false;
    this.#estopReason = '';
    this.#odometry.reset();
    this.#resetGeometry();
  }

  /** A transport that talks to this robot in-process (through the real codec). */
  transport(options: MockTransportOptions = {}): TransportFactory<'mock'> {
    return {
      type: 'mock',
      connect: async (context): Promise<Transport> => {
        const matcher = new ReplyMatcher();
        let closed = false;
        const defaults: RequestOptions = {};
        if (options.timeoutMs !== undefined) defaults.timeoutMs = options.timeoutMs;
        if (options.attempts !== undefined) defaults.attempts = options.attempts;
        return {
          type: 'mock',
          request: (seq, bytes, requestOptions) =>
            matcher.request(
              seq,
              async () => {
                if (closed) throw new HalError('NOT_CONNECTED', 'the mock transport is closed');
                const copy = bytes.slice();
                setTimeout(() => {
                  if (closed) return;
                  const reply = this.receive(copy);
                  if (reply !== undefined) matcher.deliver(context.decode(reply));
                }, options.latencyMs ?? 0);
              },
              { ...defaults, ...requestOptions },
            ),
          stats: () => matcher.stats(),
          close: async () => {
            closed = true;
            matcher.close();
          },
        };
      },
    };
  }

  /**
   * Receives one message as the robot would from the link; returns the reply bytes, or
   * undefined when the reply is lost (`dropReplies`, `unresponsive`).
   */
  receive(bytes: Uint8Array): Uint8Array | undefined {
    if (this.unresponsive) return undefined;
    const reply = this.handle(bytes);
    if (this.#dropReplies > 0) {
      this.#dropReplies -= 1;
      return undefined;
    }
    return reply;
  }

  /** Handles one request and returns the reply bytes (the protocol logic, no losses). */
  handle(bytes: Uint8Array): Uint8Array {
    this.#advance();
    let json = bytes;
    if (this.#auth !== undefined) {
      const at = bytes.length - MAC_SUFFIX_LENGTH;
      const ok =
        at > 0 &&
        bytes[at] === 0x23 &&
        decoder.decode(bytes.subarray(at + 1)) === this.#auth.mac(bytes.subarray(0, at));
      if (!ok)
        return this.#error(
          undefined,
          undefined,
          undefined,
          new Refusal('AUTH_FAILED', 'missing or wrong MAC'),
        );
      json = bytes.subarray(0, at);
    }
    let request: Json;
    try {
      const text = decoder.decode(json);
      if (hasDuplicateKey(text)) throw new Error('duplicated key');
      const value: unknown = JSON.parse(text);
      if (value === null || typeof value !== 'object' || Array.isArray(value))
        throw new Error('not an object');
      request = value as Json;
    } catch {
      return this.#error(
        undefined,
        undefined,
        undefined,
        new Refusal('MALFORMED', 'not a JSON object'),
      );
    }
    this.requests.push(request);
    const cmd = typeof request['cmd'] === 'string' ? request['cmd'] : undefined;
    const seq = typeof request['seq'] === 'number' ? request['seq'] : undefined;
    const sid = typeof request['sid'] === 'number' ? request['sid'] : undefined;
    if (cmd === 'hello') {
      this.#contact();
      return this.#hello(request, seq);
    }
    // with a key, a replayed reset must not clear an e-stop: reset_estop then needs the session
    const safety =
      cmd === 'stop' || cmd === 'estop' || (cmd === 'reset_estop' && this.#auth === undefined);
    const seedStyle = seq === undefined && sid === undefined;
    if (seedStyle && this.#auth !== undefined) {
      return this.#error(seq, sid, cmd, new Refusal('AUTH_FAILED', 'requests must carry "seq"'));
    }
    // safety commands, and seed-style requests, skip the session rules and are not remembered
    const session = !safety && !seedStyle;
    if (!seedStyle && (seq === undefined || sid === undefined)) {
      return this.#error(
        seq,
        sid,
        cmd,
        new Refusal(
          'SESSION_MISMATCH',
          '"sid" and "seq" must be given together; send hello to open a session',
        ),
      );
    }
    if (session) {
      if (sid !== this.#sid || this.#sid === 0) {
        return this.#error(
          seq,
          sid,
          cmd,
          new Refusal('SESSION_MISMATCH', 'unknown session; send hello'),
        );
      }
      const remembered = this.#memory.get(seq!);
      if (remembered !== undefined) {
        this.#contact();
        return remembered;
      }
      if (seq! <= this.#lastSeq) {
        return this.#error(
          seq,
          sid,
          cmd,
          new Refusal('STALE_SEQUENCE', 'stale seq', { seq, last_seq: this.#lastSeq }),
        );
      }
    }
    // only requests that pass the session rules, and seed-style ones, count as contact
    if (session || seedStyle || sid === this.#sid) this.#contact();
    let reply: Uint8Array;
    try {
      reply = this.#reply({ seq, sid, ok: true, cmd, ...this.#execute(cmd, request) });
    } catch (thrown) {
      if (!(thrown instanceof Refusal)) throw thrown;
      reply = this.#error(seq, sid, cmd, thrown);
    }
    if (session) {
      this.#lastSeq = seq!;
      this.#memory.set(seq!, reply);
      if (this.#memory.size > MEMORY)
        this.#memory.delete(this.#memory.keys().next().value as number);
    }
    return reply;
  }

  // -- protocol -------------------------------------------------------------------------------

  #hello(request: Json, seq: number | undefined): Uint8Array {
    const nonce = typeof request['nonce'] === 'string' ? request['nonce'] : undefined;
    const key = `${nonce ?? ''}/${seq ?? ''}`;
    if (this.#helloReply !== undefined && nonce !== undefined && key === this.#helloKey)
      return this.#helloReply;
    if (this.#auth !== undefined && (nonce === undefined || seq === undefined)) {
      return this.#error(
        seq,
        undefined,
        'hello',
        new Refusal('AUTH_FAILED', 'hello must carry seq and nonce'),
      );
    }
    this.#sid = 1 + Math.floor(Math.random() * 0xfffffffe);
    this.#lastSeq = seq ?? 0;
    this.#memory.clear();
    this.#accLeft.reset();
    this.#accRight.reset();
    const reply: Json = { seq, sid: this.#sid, ok: true, cmd: 'hello' };
    if (nonce !== undefined) reply['nonce'] = nonce;
    Object.assign(reply, {
      device_id: this.deviceId,
      firmware_version: '1.0.0-mock',
      protocol_version: '1.0',
      auth: this.#auth !== undefined,
      capabilities: [
        'locomotion.differential:v1.0',
        `locomotion.stepper:v1.0:steps_per_rev=${this.#config.steps_per_revolution}`,
        'communication.led:v1.0',
        'safety.estop:v1.0',
        'safety.host_timeout:v1.0',
      ],
      config: this.#configJson(),
    });
    this.#helloKey = key;
    this.#helloReply = this.#reply(reply);
    return this.#helloReply;
  }

  #execute(cmd: string | undefined, r: Json): Json {
    switch (cmd) {
      case 'heartbeat':
        return {
          uptime_ms: this.#uptimeMs(),
          running: this.#motion !== undefined,
          estop: this.#estop,
        };
      case 'move_steps':
        return this.#startMove(this.#int(r, 'left'), this.#int(r, 'right'), r);
      case 'move_cm': {
        this.#notEstopped();
        const left = this.#accLeft.add(this.#num(r, 'left_cm'));
        const right = this.#accRight.add(this.#num(r, 'right_cm'));
        return this.#startMove(left, right, r);
      }
      case 'rotate_deg': {
        this.#notEstopped();
        const arc = rotationArcCm(this.#num(r, 'degrees'), this.#geometry());
        const left = this.#accLeft.add(-arc);
        const right = this.#accRight.add(arc);
        return this.#startMove(left, right, r);
      }
      case 'drive':
        return this.#drive(r);
      case 'stop': {
        const stopped = this.#stopMotion('stopped');
        return { stopped, left_steps: this.#left, right_steps: this.#right };
      }
      case 'get_status':
        return this.#status();
      case 'set_config':
        return this.#setConfig(r);
      case 'set_led': {
        const pattern = typeof r['pattern'] === 'string' ? r['pattern'] : 'solid';
        if (!['solid', 'blink', 'pulse', 'off'].includes(pattern)) {
          throw new Refusal(
            'INVALID_PARAMETER',
            '"pattern" must be one of solid, blink, pulse, off',
            {
              field: 'pattern',
            },
          );
        }
        this.#led =
          pattern === 'off'
            ? { r: 0, g: 0, b: 0, pattern }
            : { r: this.#int(r, 'r'), g: this.#int(r, 'g'), b: this.#int(r, 'b'), pattern };
        return { led: { ...this.#led } };
      }
      case 'estop': {
        const reason = typeof r['reason'] === 'string' ? r['reason'].slice(0, 63) : 'estop command';
        this.#stopMotion('estop');
        this.#estop = true;
        this.#estopReason = reason;
        this.#trip('estop_command', reason);
        return { estop: true, estop_reason: reason };
      }
      case 'reset_estop': {
        const was = this.#estop;
        this.#estop = false;
        this.#estopReason = '';
        return { estop: false, was_estopped: was };
      }
      default:
        throw new Refusal('UNKNOWN_COMMAND', `unknown command ${JSON.stringify(cmd)}`);
    }
  }

  #startMove(left: number, right: number, r: Json): Json {
    this.#notEstopped();
    for (const [field, steps] of [
      ['left', left],
      ['right', right],
    ] as const) {
      if (Math.abs(steps) > MAX_STEPS) {
        this.#stopMotion('estop');
        this.#estop = true;
        this.#estopReason = `step limit: "${field}" ${steps} steps`;
        this.#trip('step_limit', `${field} ${steps}`);
        throw new Refusal(
          'RANGE_EXCEEDED',
          `"${field}" gives ${steps} steps; the limit is ${MAX_STEPS} steps per command (emergency stop latched)`,
          { field, min: -MAX_STEPS, max: MAX_STEPS, value: steps, estop: true },
        );
      }
    }
    const { speed, clamped } = this.#speed(r);
    const plan = new MovePlan(left, right, speed, this.#config.acceleration_steps_per_s2);
    this.#begin(plan, plan.durationUs);
    return {
      move_id: this.#moveId,
      left_steps: left,
      right_steps: right,
      speed,
      speed_clamped: clamped,
      duration_ms: Math.ceil(plan.durationUs / 1000),
      duration_us: plan.durationUs,
    };
  }

  #drive(r: Json): Json {
    this.#notEstopped();
    let left = this.#int(r, 'left_sps');
    let right = this.#int(r, 'right_sps');
    const duration =
      r['duration_ms'] === undefined || r['duration_ms'] === null
        ? undefined
        : this.#int(r, 'duration_ms');
    const max = this.#config.max_speed_steps_per_s;
    const fastest = Math.max(Math.abs(left), Math.abs(right));
    const clamped = fastest > max;
    if (clamped) {
      left = Math.trunc((left * max) / fastest);
      right = Math.trunc((right * max) / fastest);
    }
    const reply: Json = { left_sps: left, right_sps: right, speed_clamped: clamped };
    if (duration !== undefined) reply['duration_ms'] = duration;
    if (left === 0 && right === 0) {
      this.#stopMotion('stopped');
      return { move_id: this.#moveId, ...reply, running: false };
    }
    const plan = new VelocityPlan(left, right, this.#config.acceleration_steps_per_s2);
    this.#begin(plan, duration === undefined ? Number.POSITIVE_INFINITY : duration * 1000);
    return { move_id: this.#moveId, ...reply, running: true };
  }

  #begin(plan: StepPlan, endUs: number): void {
    this.#stopMotion('replaced');
    this.#moveId += 1;
    this.motionsStarted += 1;
    this.#moveLeft = 0;
    this.#moveRight = 0;
    this.#outcome = 'running';
    if (endUs === 0) {
      this.#outcome = 'done';
      return;
    }
    this.#motion = {
      plan,
      startUs: this.#robotUs(),
      endUs,
      baseLeft: this.#left,
      baseRight: this.#right,
      left: 0,
      right: 0,
    };
  }

  #status(): Json {
    const pose = this.#odometry.pose;
    const v =
      this.#motion === undefined
        ? { left: 0, right: 0 }
        : this.#motion.plan.velocityAt(this.#robotUs() - this.#motion.startUs);
    return {
      x_cm: pose.xCm,
      y_cm: pose.yCm,
      heading_rad: pose.headingRad,
      left_steps: this.#left,
      right_steps: this.#right,
      running: this.#motion !== undefined,
      move_id: this.#moveId,
      move_outcome: this.#outcome,
      move_left_steps: this.#moveLeft,
      move_right_steps: this.#moveRight,
      left_sps: v.left,
      right_sps: v.right,
      uptime_ms: this.#uptimeMs(),
      safety: {
        estop: this.#estop,
        estop_reason: this.#estopReason,
        trips: this.#trips,
        last_trip: this.#lastTrip,
        host_timeout_ms: this.#config.host_timeout_ms,
        ms_since_host: Math.max(0, Math.floor((this.#robotUs() - this.#lastHostUs) / 1000)),
        coils_on: this.#motion !== undefined,
      },
      led: { ...this.#led },
    };
  }

  #setConfig(r: Json): Json {
    const next = { ...this.#config };
    const ranges: Record<keyof typeof next, [number, number, boolean]> = {
      wheel_diameter_cm: [0.5, 50, false],
      wheel_base_cm: [1, 100, false],
      steps_per_revolution: [100, 100000, true],
      max_speed_steps_per_s: [1, 2048, true],
      acceleration_steps_per_s2: [1, 100000, true],
      host_timeout_ms: [500, 10000, true],
    };
    for (const [field, [min, max, integer]] of Object.entries(ranges) as Array<
      [keyof typeof next, [number, number, boolean]]
    >) {
      if (r[field] === undefined || r[field] === null) continue;
      const value = integer ? this.#int(r, field) : this.#num(r, field);
      if (value < min || value > max)
        throw new Refusal('RANGE_EXCEEDED', `"${field}" must be ${min}..${max}`, {
          field,
          min,
          max,
          value,
        });
      next[field] = value;
    }
    this.#config = next;
    this.#resetGeometry();
    return { config: this.#configJson() };
  }

  // -- motion and time ------------------------------------------------------------------------

  #robotUs(): number {
    return Math.floor((this.#now() - this.#bootAt) * 1000 * this.#timeScale);
  }

  #uptimeMs(): number {
    return Math.floor(this.#robotUs() / 1000);
  }

  /** Brings the wheels up to the present (finishing or timing out the motion). */
  #advance(): void {
    const m = this.#motion;
    if (m === undefined) return;
    const now = this.#robotUs();
    const timeoutAt = this.#lastHostUs + this.#config.host_timeout_ms * 1000;
    const end = Math.min(m.startUs + m.plan.durationUs, m.startUs + m.endUs);
    const until = Math.min(now, end, timeoutAt);
    this.#moveTo(m, until - m.startUs);
    if (until === timeoutAt && timeoutAt <= now && timeoutAt < end) {
      this.#motion = undefined;
      this.#outcome = 'host_timeout';
      this.#trip('host_timeout', `no request for ${this.#config.host_timeout_ms} ms`);
    } else if (until === end && end <= now) {
      this.#motion = undefined;
      this.#outcome = 'done';
    }
  }

  #moveTo(m: Motion, elapsedUs: number): void {
    const steps = m.plan.stepsAt(Math.max(0, elapsedUs));
    this.#left = m.baseLeft + steps.left;
    this.#right = m.baseRight + steps.right;
    this.#moveLeft = steps.left;
    this.#moveRight = steps.right;
    this.#odometry.update(this.#left, this.#right);
  }

  #stopMotion(outcome: MoveOutcome): boolean {
    this.#advance();
    if (this.#motion === undefined) return false;
    this.#motion = undefined;
    this.#outcome = outcome;
    return true;
  }

  #contact(): void {
    this.#lastHostUs = this.#robotUs();
  }

  #trip(reason: string, detail: string): void {
    this.#trips += 1;
    this.#lastTrip = { reason, detail, uptime_ms: this.#uptimeMs() };
  }

  #notEstopped(): void {
    if (this.#estop)
      throw new Refusal('EMERGENCY_STOPPED', 'the emergency stop is latched', {
        reason: this.#estopReason,
      });
  }

  #speed(r: Json): { speed: number; clamped: boolean } {
    const max = this.#config.max_speed_steps_per_s;
    if (r['speed'] === undefined || r['speed'] === null) return { speed: max, clamped: false };
    const speed = this.#num(r, 'speed');
    if (speed <= 0)
      throw new Refusal('RANGE_EXCEEDED', `"speed" must be 1..${max} steps/s`, {
        field: 'speed',
        min: 1,
        max,
        value: speed,
      });
    if (speed > max) return { speed: max, clamped: true };
    if (speed < 1) return { speed: 1, clamped: true };
    return { speed, clamped: false };
  }

  #num(r: Json, field: string): number {
    const value = r[field];
    if (typeof value !== 'number' || !Number.isFinite(value))
      throw new Refusal('INVALID_PARAMETER', `"${field}" must be a number`, { field });
    return value;
  }

  #int(r: Json, field: string): number {
    const value = this.#num(r, field);
    if (!Number.isInteger(value))
      throw new Refusal('INVALID_PARAMETER', `"${field}" must be an integer`, { field });
    return value;
  }

  #geometry() {
    return {
      stepsPerRevolution: this.#config.steps_per_revolution,
      wheelDiameterCm: this.#config.wheel_diameter_cm,
      wheelBaseCm: this.#config.wheel_base_cm,
    };
  }

  #resetGeometry(): void {
    const g = this.#geometry();
    this.#accLeft = new StepAccumulator(g);
    this.#accRight = new StepAccumulator(g);
    const pose = this.#odometry.pose;
    this.#odometry = new OdometryIntegrator(g, pose, this.#left, this.#right);
  }

  #configJson(): Json {
    return { ...this.#config, max_steps_per_command: MAX_STEPS };
  }

  #reply(value: Json): Uint8Array {
    const json = encoder.encode(JSON.stringify(value));
    if (this.#auth === undefined) return json;
    return encoder.encode(`${decoder.decode(json)}#${this.#auth.mac(json)}`);
  }

  #error(
    seq: number | undefined,
    sid: number | undefined,
    cmd: string | undefined,
    refusal: Refusal,
  ): Uint8Array {
    const reply: Json = {
      seq,
      sid,
      ok: false,
      cmd,
      error: { code: refusal.code, message: refusal.message, details: refusal.details },
    };
    return this.#reply(reply);
  }
}

/** Whether a JSON text repeats a key within one object (the protocol calls that MALFORMED). */
function hasDuplicateKey(text: string): boolean {
  const stack: Array<Set<string> | undefined> = [];
  let expectKey = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === '"') {
      let end = i + 1;
      while (end < text.length && text[end] !== '"') end += text[end] === '\\' ? 2 : 1;
      const keys = stack[stack.length - 1];
      if (expectKey && keys !== undefined) {
        const key = text.slice(i + 1, end);
        if (keys.has(key)) return true;
        keys.add(key);
      }
      expectKey = false;
      i = end;
    } else if (c === '{') {
      stack.push(new Set());
      expectKey = true;
    } else if (c === '[') {
      stack.push(undefined);
    } else if (c === '}' || c === ']') {
      stack.pop();
    } else if (c === ',') {
      expectKey = stack[stack.length - 1] !== undefined;
    }
  }
  return false;
}
