import { HalError, isHalError } from '@hal/types';
import { scoped } from '@hal/types';
import type { ScopedLogger } from '@hal/types';
import type { WireReply } from './protocol/codec.js';
import { helloUnanswered, randomNonce, robotError } from './session-errors.js';
import type { SessionOptions, SessionState } from './session-options.js';
import { fastReply } from './protocol/reply-fast.js';
import { HelloReplySchema, REPLY_SCHEMAS } from './protocol/schemas.js';
import type { Command, HelloReply, ReplyOf, RequestParams } from './protocol/schemas.js';
import {
  DEFAULT_SAFETY_LANE,
  isMotionCommand,
  laneAttempts,
  laneBound,
  StopSignal,
} from './safety-lane.js';
import type { SafetyCommand, SafetyInterrupt, SafetyLaneTiming } from './safety-lane.js';
import { DEFAULT_ATTEMPTS } from './transport/transport.js';
import type { RequestOptions } from './transport/transport.js';

export type { SessionOptions, SessionState } from './session-options.js';
export { robotError } from './session-errors.js';

/** Commands the robot executes whatever the session (protocol 1.1, section 4, rule 1). */
const SAFETY_COMMANDS: ReadonlySet<Command> = new Set(['stop', 'estop', 'reset_estop']);
/** A command's options when none are given (one object, not one per call). */
const NO_OPTIONS: RequestOptions = Object.freeze({});
/** A request's options over the link's timing: a new object only when both set some. */
const withTiming = (timing: RequestOptions | undefined, options: RequestOptions) =>
  timing === undefined ? options : options === NO_OPTIONS ? timing : { ...timing, ...options };

/**
 * One host session with the robot over a transport: `hello`, then requests numbered by a
 * strictly increasing `seq`, one at a time (so a retry can never arrive after a newer request and
 * be refused as stale). It sends heartbeats while idle, turns a dead link or a replaced session
 * into NOT_CONNECTED, and keeps saying `hello` until the robot answers again.
 *
 * `stop` and `estop` take the safety lane instead (protocol 1.1, section 4.1): sent at once,
 * beside whatever request is pending, and resent every few ms until acknowledged. The robot
 * executes them whatever their `seq` without advancing the session's highest `seq`, so the
 * pending request's retries stay valid; and it refuses a motion command numbered below a stop it
 * executed, so a move sent before a stop can never start after it. A motion command still waiting
 * in the queue when a stop is issued is not sent at all.
 */
export class Session {
  readonly #options: SessionOptions;
  readonly #log: ScopedLogger;
  #state: SessionState = 'idle';
  #seq = 0;
  #sid: number | undefined;
  /** Whether a request holds the queue; the tasks waiting for it, in order. */
  #running = false;
  readonly #waiting: (() => void)[] = [];
  #busy = 0;
  #lastRequestAt = 0;
  #heartbeat: ReturnType<typeof setTimeout> | undefined;
  #heartbeatPaused = false;
  #reconnectTimer: ReturnType<typeof setTimeout> | undefined;
  #hello: HelloReply | undefined;
  readonly #stops = new StopSignal();
  /** Replies whose data did not match the command's schema. */
  malformedReplies = 0;

  constructor(options: SessionOptions) {
    this.#options = options;
    this.#log = scoped(options.logger, 'hal:physical:session');
  }

  get state(): SessionState {
    return this.#state;
  }

  /** The current session id. */
  get sid(): number | undefined {
    return this.#sid;
  }

  /** The last `hello` reply. */
  get hello(): HelloReply | undefined {
    return this.#hello;
  }

  /**
   * Opens the session (`hello`) and starts the heartbeat. Throws NOT_CONNECTED when nothing
   * answers, AUTH_FAILED when the robot answers but not with our key. `options` overrides the
   * hello's timeout and attempts (how long connecting may take).
   */
  async open(options?: RequestOptions): Promise<HelloReply> {
    const request = { ...this.#options.request?.(), ...options };
    const hello = await this.#exclusive(() => this.#sayHello(request));
    this.#setState('connected', 'hello answered');
    this.#scheduleBeat();
    await this.#options.onConnected?.(hello, false);
    return hello;
  }

  /** Stops sending heartbeats (to test the robot's host timeout); requests still go out. */
  pauseHeartbeat(): void {
    this.#heartbeatPaused = true;
  }

  resumeHeartbeat(): void {
    this.#heartbeatPaused = false;
  }

  /**
   * Sends one command and returns its reply data, checked against the command's schema. Throws a
   * HalError: the robot's own code when it refuses, NOT_CONNECTED when the link or the session
   * is lost, MALFORMED when the reply does not match the protocol.
   */
  async command<C extends Command>(
    cmd: C,
    params: RequestParams[C],
    options: RequestOptions = NO_OPTIONS,
  ): Promise<ReplyOf<C>> {
    // the queue, the send, the reply's checks and the failure hook in this one async function:
    // each further layer was a promise and a suspended frame more per request
    try {
      if (cmd === 'stop' || cmd === 'estop') {
        // the safety lane; `options` bound its total wait (attempts x timeout)
        const lane = laneBound(options);
        const safety = params as RequestParams[SafetyCommand];
        return (await this.safetyCommand(cmd, safety, lane)) as ReplyOf<C>;
      }
      const safety = SAFETY_COMMANDS.has(cmd);
      this.#checkUsable(cmd, safety);
      const epoch = this.#stops.epoch;
      this.#busy += 1;
      try {
        if (this.#running) await new Promise<void>((start) => this.#waiting.push(start));
        this.#running = true;
        this.#checkUsable(cmd, safety);
        if (isMotionCommand(cmd) && epoch !== this.#stops.epoch) throw this.#stops.overtaken(cmd);
        const seq = this.#nextSeq();
        const bytes = this.#options.codec.encode({ cmd, seq, sid: this.#sid, ...params });
        const timing = this.#options.request?.();
        let reply: WireReply;
        // no stamp before the send: no heartbeat goes out while a request is under way (#busy)
        try {
          reply = await this.#options.transport.request(seq, bytes, withTiming(timing, options));
        } catch (thrown) {
          throw this.#sendFailed(cmd, thrown);
        } finally {
          this.#lastRequestAt = performance.now();
        }
        return this.#accept(cmd, reply);
      } finally {
        this.#release();
      }
    } catch (thrown) {
      this.#options.onCommandFailed?.(thrown);
      throw thrown;
    }
  }

  /** The checked data of a reply to `cmd`, or the HalError it amounts to. */
  #accept<C extends Command>(cmd: C, reply: WireReply): ReplyOf<C> {
    if (!reply.ok) {
      if (reply.error?.code === 'SESSION_MISMATCH') {
        this.#lose('the robot no longer knows this session');
        throw new HalError(
          'NOT_CONNECTED',
          `the robot's session changed (it restarted or another host connected); reconnecting`,
          {
            cause: robotError(cmd, reply),
            details: { command: cmd, robotCode: 'SESSION_MISMATCH' },
          },
        );
      }
      throw robotError(cmd, reply);
    }
    return this.#replyData(cmd, reply);
  }

  /**
   * The data of a successful reply, checked against the command's schema (the hand-checked path
   * first, zod when it is unsure) and reported through `onReply`; MALFORMED when it does not match.
   */
  #replyData<C extends Command>(cmd: C, reply: WireReply): ReplyOf<C> {
    let data = fastReply(cmd, reply);
    if (data === undefined) {
      const parsed = REPLY_SCHEMAS[cmd].safeParse(reply);
      if (!parsed.success) {
        this.malformedReplies += 1;
        const issue = parsed.error.issues[0];
        throw new HalError(
          'MALFORMED',
          `the robot's "${cmd}" reply does not match protocol 1.1: ${issue?.path.join('.') ?? ''} ${issue?.message ?? ''}`.trim(),
          { details: { command: cmd } },
        );
      }
      data = parsed.data as ReplyOf<C>;
    }
    this.#options.onReply?.(cmd, data as Record<string, unknown>);
    return data;
  }

  /** The number of stops issued so far (see {@link interrupted}). */
  get safetyEpoch(): number {
    return this.#stops.epoch;
  }

  /** Resolves when the robot acknowledges a stop issued after `epoch` (never rejects). */
  interrupted(epoch: number): Promise<SafetyInterrupt> {
    return this.#stops.interrupted(epoch);
  }

  /**
   * The safety lane: sends `stop` or `estop` now, whatever request is pending, and resends it
   * every `resendMs` until the robot answers (at most `totalMs`). Works while the link is being
   * re-established (the robot executes a stop whatever its session). Throws NOT_CONNECTED when
   * no session was ever opened or the link is closed, or when no reply came in time.
   */
  async safetyCommand<C extends SafetyCommand>(
    cmd: C,
    params: RequestParams[C],
    timing?: SafetyLaneTiming,
  ): Promise<ReplyOf<C>> {
    if (this.#state === 'closed' || this.#sid === undefined) {
      throw new HalError('NOT_CONNECTED', `cannot send "${cmd}": the robot is not connected`, {
        details: { command: cmd, state: this.#state },
      });
    }
    const epoch = this.#stops.issue(cmd);
    const seq = this.#nextSeq();
    const bytes = this.#options.codec.encode({ cmd, seq, sid: this.#sid, ...params });
    const lane = laneAttempts(timing ?? this.#options.safetyLane?.() ?? DEFAULT_SAFETY_LANE);
    let reply: WireReply;
    try {
      this.#lastRequestAt = performance.now();
      reply = await this.#options.transport.request(seq, bytes, lane);
    } catch (thrown) {
      // unacknowledged for the lane's whole budget: the link is as lost as after any timeout
      if (isHalError(thrown) && thrown.code === 'TIMEOUT') this.#lose(`no reply to "${cmd}"`);
      throw new HalError('NOT_CONNECTED', `the robot did not acknowledge "${cmd}"`, {
        cause: thrown,
        details: { command: cmd },
      });
    }
    if (!reply.ok) throw robotError(cmd, reply);
    const data = this.#replyData(cmd, reply);
    this.#stops.acknowledged(epoch, { cmd, reply: data } as SafetyInterrupt);
    return data;
  }

  /** Stops the heartbeat and reconnection; later commands fail with NOT_CONNECTED. */
  close(): void {
    clearTimeout(this.#heartbeat);
    clearTimeout(this.#reconnectTimer);
    this.#setState('closed', 'closed by the host');
  }

  #checkUsable(cmd: Command, safety: boolean): void {
    if (this.#state === 'closed') {
      throw new HalError('NOT_CONNECTED', `cannot send "${cmd}": the link is closed`);
    }
    if (this.#sid === undefined || (this.#state !== 'connected' && !safety)) {
      throw new HalError(
        'NOT_CONNECTED',
        `cannot send "${cmd}": the robot is not connected (reconnecting)`,
        { details: { command: cmd, state: this.#state } },
      );
    }
  }

  #nextSeq(): number {
    this.#seq += 1;
    return this.#seq;
  }

  /** What a failed request amounts to: a timeout loses the link (NOT_CONNECTED). */
  #sendFailed(cmd: string, thrown: unknown): unknown {
    if (isHalError(thrown) && thrown.code === 'TIMEOUT') {
      this.#lose(`no reply to "${cmd}"`);
      return new HalError('NOT_CONNECTED', `the robot did not answer "${cmd}": ${thrown.message}`, {
        cause: thrown,
        details: { command: cmd, ...thrown.details },
      });
    }
    return thrown;
  }

  async #sayHello(options: RequestOptions | undefined): Promise<HelloReply> {
    const seq = this.#nextSeq();
    // always a nonce: it lets the robot recognise a resent hello as a retry (same session), and
    // lets us tell its reply from a late reply to an older hello
    const nonce = randomNonce();
    const params: RequestParams['hello'] = {
      client: this.#options.client ?? '@hal/physical',
      nonce,
    };
    // a copy: the codec's pool reuses its bytes, and these are resent one attempt at a time
    const bytes = this.#options.codec.encode({ cmd: 'hello', seq, ...params }).slice();
    const codec = this.#options.codec;
    const rejected = { ...codec.macRejections };
    const attempts = options?.attempts ?? DEFAULT_ATTEMPTS;
    let reply: WireReply | undefined;
    // One attempt at a time (the same bytes and seq, so still one hello to the robot): a reply
    // that fails our MAC check means a wrong key, said at once rather than after every attempt.
    for (let sent = 1; reply === undefined; sent++) {
      try {
        reply = await this.#options.transport.request(seq, bytes, {
          ...options,
          attempts: 1,
          callerAttempt: { attempt: sent, of: attempts },
        });
      } catch (cause) {
        const timedOut = isHalError(cause) && cause.code === 'TIMEOUT';
        const refusedMac =
          codec.macRejections.mismatched > rejected.mismatched ||
          codec.macRejections.unsigned > rejected.unsigned;
        if (!timedOut || refusedMac || sent >= attempts) {
          throw helloUnanswered(cause, options, rejected, codec);
        }
      }
    }
    if (!reply.ok) throw robotError('hello', reply);
    const parsed = HelloReplySchema.safeParse(reply);
    if (!parsed.success) {
      this.malformedReplies += 1;
      throw new HalError('MALFORMED', "the robot's hello reply does not match protocol 1.1");
    }
    if (parsed.data.nonce !== nonce) {
      throw new HalError('AUTH_FAILED', "the robot's hello reply does not echo our nonce");
    }
    if (!parsed.data.protocol_version.startsWith('1.')) {
      throw new HalError(
        'NOT_IMPLEMENTED',
        `the robot speaks protocol ${parsed.data.protocol_version}; this host speaks 1.x`,
      );
    }
    this.#sid = parsed.data.sid;
    this.#hello = parsed.data;
    this.#log.info('session open', {
      sid: parsed.data.sid,
      deviceId: parsed.data.device_id,
      firmware: parsed.data.firmware_version,
    });
    return parsed.data;
  }

  #scheduleBeat(): void {
    if (this.#state === 'closed') return;
    this.#heartbeat = setTimeout(() => {
      this.#beat();
      this.#scheduleBeat();
    }, this.#options.heartbeatIntervalMs());
  }

  /** Sends a heartbeat unless a request went out within the last half period. */
  #beat(): void {
    if (this.#state !== 'connected' || this.#heartbeatPaused || this.#busy > 0) return;
    const since = performance.now() - this.#lastRequestAt;
    if (since < this.#options.heartbeatIntervalMs() / 2) return;
    this.command('heartbeat', {}).catch((error: unknown) =>
      this.#log.debug('heartbeat failed', { error: String(error) }),
    );
  }

  #lose(reason: string): void {
    if (this.#state !== 'connected') return;
    this.#setState('lost', reason);
    this.#scheduleReconnect();
  }

  #scheduleReconnect(): void {
    clearTimeout(this.#reconnectTimer);
    this.#reconnectTimer = setTimeout(
      () => void this.#reconnect(),
      this.#options.reconnectIntervalMs,
    );
  }

  async #reconnect(): Promise<void> {
    if (this.#state !== 'lost') return;
    try {
      const hello = await this.#exclusive(() =>
        this.#sayHello({ ...this.#options.request?.(), attempts: 1 }),
      );
      if (this.#state !== 'lost') return;
      this.#setState('connected', 'hello answered again');
      await this.#options.onConnected?.(hello, true);
    } catch (error) {
      this.#log.debug('reconnect failed', { error: String(error) });
      if (this.#state === 'lost') this.#scheduleReconnect();
    }
  }

  #setState(state: SessionState, reason: string): void {
    if (this.#state === state || this.#state === 'closed') return;
    this.#state = state;
    this.#log.info(`link ${state}`, { reason });
    this.#options.onStateChange?.(state, reason);
  }

  /**
   * Runs `task` once every task queued before it has ended: at once when none is running (no
   * promise hop), else when the one before hands over.
   */
  async #exclusive<T>(task: () => Promise<T>): Promise<T> {
    this.#busy += 1;
    try {
      if (this.#running) await new Promise<void>((start) => this.#waiting.push(start));
      this.#running = true;
      return await task();
    } finally {
      this.#release();
    }
  }

  /** Ends a request's hold on the queue: the next one waiting runs, with #running still set. */
  #release(): void {
    this.#busy -= 1;
    const next = this.#waiting.shift();
    if (next === undefined) this.#running = false;
    else next();
  }
}
