import {
  CAPABILITIES,
  HalBoundary,
  HALConfigSchema,
  HalError,
  isHalError,
  robotConfig,
  stepsPerCm,
  V1_ROBOT,
} from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALConfig,
  HardwareAbstractionLayer,
  IMUReading,
  LocomotionInterface,
  Pose,
  RobotConfig,
  SafetyInterface,
  SafetyStatus,
  VisionInterface,
} from '@hal/types';
import { normalizeAngle } from '@hal/kinematics';
import { MjpegCamera } from './camera/mjpeg.js';
import { scoped, silentLogger } from './logger.js';
import type { Logger, ScopedLogger } from './logger.js';
import { PoseTracker } from './pose-tracker.js';
import { createAuthenticator } from './protocol/auth.js';
import { MessageCodec } from './protocol/codec.js';
import type {
  Command,
  DeviceConfig,
  ReplyOf,
  HelloReply,
  MotionReply,
  RequestParams,
  StatusReply,
} from './protocol/schemas.js';
import { Session } from './session.js';
import type { SessionState } from './session.js';
import { serialTransport } from './transport/serial.js';
import { DEFAULT_ATTEMPTS, DEFAULT_REPLY_TIMEOUT_MS } from './transport/transport.js';
import type {
  RequestOptions,
  SerialLinkStats,
  Transport,
  TransportFactory,
  TransportStats,
} from './transport/transport.js';
import { udpTransport } from './transport/udp.js';

/** Options of {@link PhysicalHAL}, beside its {@link HALConfig}. */
export interface PhysicalHALOptions {
  /** The link to the robot; default built from `config.connection` (wifi: UDP, serial: serial). */
  transport?: TransportFactory;
  /** Where the HAL logs (namespaces `hal:physical:*`). Default: nowhere. */
  logger?: Logger;
  /** The clock results are stamped with, ms. Default `Date.now`. */
  now?: () => number;
  /**
   * How much faster than real time the robot's clock runs (1 for a real robot; the emulator's
   * `--time-scale`). Scales the heartbeat, polling and motion timeouts.
   */
  timeScale?: number;
  /** Heartbeat period, robot ms. Default a quarter of the robot's host timeout, at most 500. */
  heartbeatIntervalMs?: number;
  /** Period of `get_status` polls while a motion runs, robot ms. Default 100. */
  pollIntervalMs?: number;
  /** While the link is lost, say `hello` again this often, real ms. Default 1000. */
  reconnectIntervalMs?: number;
  /**
   * Resend an unanswered request after this long, real ms. Default a quarter of the robot's host
   * timeout (500 ms), scaled by `timeScale`, so that one lost datagram can never let the host
   * timeout fire; resending the same bytes keeps every request exactly-once.
   */
  requestTimeoutMs?: number;
  /**
   * Give a request up after this many sends. Default: as many as fit in the protocol's
   * 3 x 2000 ms budget.
   */
  attempts?: number;
  /** Extra time a motion may take beyond its planned duration, real ms. Default 2000. */
  motionTimeoutMarginMs?: number;
  /** Names the host software in `hello`. */
  client?: string;
}

/** What the robot said about itself when the session opened. */
export interface RobotIdentity {
  deviceId: string;
  firmwareVersion: string;
  protocolVersion: string;
  auth: boolean;
  capabilities: string[];
  config: DeviceConfig;
}

const MAX_POWER = 255;

function deviceRobotConfig(base: RobotConfig, c: DeviceConfig): RobotConfig {
  return robotConfig({
    ...base,
    stepsPerRevolution: c.steps_per_revolution,
    wheelDiameterCm: c.wheel_diameter_cm,
    wheelBaseCm: c.wheel_base_cm,
    maxSpeedStepsPerS: c.max_speed_steps_per_s,
    accelerationStepsPerS2: c.acceleration_steps_per_s2,
    hostTimeoutMs: c.host_timeout_ms,
    maxStepsPerCommand: Math.min(base.maxStepsPerCommand, c.max_steps_per_command ?? 40960),
  });
}

function defaultTransport(config: HALConfig, timeoutMs: number): TransportFactory {
  const connection = config.connection;
  if (connection?.type === 'wifi' && connection.host !== undefined) {
    return udpTransport(
      connection.udpPort === undefined
        ? { host: connection.host }
        : { host: connection.host, port: connection.udpPort },
    );
  }
  if (connection?.type === 'serial' && connection.port !== undefined) {
    // frames are resent as quickly as requests, so a corrupted frame cannot outlast the host timeout
    return serialTransport(
      connection.baudRate === undefined
        ? { path: connection.port, timeoutMs }
        : { path: connection.port, baudRate: connection.baudRate, timeoutMs },
    );
  }
  throw new HalError(
    'INVALID_PARAMETER',
    '"connection" must be { type: "wifi", host } or { type: "serial", port } (or pass a transport)',
    { details: { parameter: 'connection' } },
  );
}

const sleep = (ms: number) => new Promise<void>((resolve) => setTimeout(resolve, ms));

/**
 * The HAL of the physical V1 stepper cube, spoken to over protocol 1.0 (docs/protocol.md) through
 * a UDP or serial transport. Every public call goes through the shared {@link HalBoundary}; a
 * motion resolves when the robot reports it finished; the pose is dead-reckoned on the host from
 * the robot's step counters, in a frame anchored where the robot stood at `initialize()`.
 */
export class PhysicalHAL implements HardwareAbstractionLayer {
  readonly mode = 'physical' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;

  readonly #config: HALConfig;
  readonly #options: PhysicalHALOptions;
  readonly #log: ScopedLogger;
  readonly #robotLog: ScopedLogger;
  readonly #now: () => number;
  readonly #timeScale: number;
  readonly #boundary: HalBoundary;
  readonly #camera: MjpegCamera | undefined;
  #robot: RobotConfig;
  #tracker: PoseTracker;
  #transport: Transport | undefined;
  #session: Session | undefined;
  #identity: RobotIdentity | undefined;
  #initialized = false;
  /** The robot's own latch, as its last reply said. */
  #robotEstop = false;
  #robotEstopReason: string | undefined;
  /**
   * The host's latch: set by emergencyStop() before anything is sent, cleared only by an accepted
   * reset. It keeps motion refused even if the stop never reached the robot, or the robot restarted
   * (which clears its own latch); on reconnection the HAL e-stops the robot again.
   */
  #hostEstop: string | undefined;
  #lastStatus: StatusReply | undefined;
  #linkError: string | undefined;
  #initializing: Promise<void> | undefined;

  constructor(config: HALConfig, options: PhysicalHALOptions = {}) {
    const parsed = HALConfigSchema.safeParse(config);
    if (!parsed.success) {
      const issue = parsed.error.issues[0];
      throw new HalError(
        'INVALID_PARAMETER',
        `PhysicalHAL config: "${issue?.path.join('.') ?? 'config'}" ${issue?.message ?? 'is invalid'}`,
      );
    }
    if (parsed.data.mode !== 'physical') {
      throw new HalError('INVALID_PARAMETER', `PhysicalHAL config: "mode" must be "physical"`);
    }
    const timeScale = options.timeScale ?? 1;
    if (!(timeScale > 0) || !Number.isFinite(timeScale)) {
      throw new HalError('INVALID_PARAMETER', `"timeScale" must be a finite number > 0`);
    }
    this.#config = parsed.data;
    this.#options = options;
    this.#timeScale = timeScale;
    this.#now = options.now ?? Date.now;
    const logger = options.logger ?? silentLogger;
    this.#log = scoped(logger, 'hal:physical');
    this.#robotLog = scoped(logger, 'hal:physical:log');
    const overrides = Object.fromEntries(
      Object.entries(parsed.data.robot ?? {}).filter(([, value]) => value !== undefined),
    ) as Partial<RobotConfig>;
    this.#robot = robotConfig({ ...V1_ROBOT, ...overrides });
    this.#tracker = new PoseTracker(this.#robot, () => performance.now(), timeScale);
    const cameraUrl = parsed.data.connection?.cameraUrl;
    this.#camera =
      cameraUrl === undefined ? undefined : new MjpegCamera({ url: cameraUrl, logger });
    this.#boundary = new HalBoundary({
      mode: this.mode,
      config: () => this.#robot,
      isEmergencyStopped: () => this.#isEstopped(),
      // initialised is enough here: a lost link is reported by the call itself, as NOT_CONNECTED
      isReady: () => this.#initialized,
      now: this.#now,
    });
    this.locomotion = this.#makeLocomotion();
    this.vision = this.#makeVision();
    this.communication = this.#makeCommunication();
    this.safety = this.#makeSafety();
  }

  /** Opens the link and the session, learns who the robot is and anchors the pose. */
  async initialize(): Promise<void> {
    if (this.#initialized) return;
    this.#initializing ??= this.#open().finally(() => {
      this.#initializing = undefined;
    });
    return this.#initializing;
  }

  async #open(): Promise<void> {
    const logger = this.#options.logger ?? silentLogger;
    const factory =
      this.#options.transport ?? defaultTransport(this.#config, this.#requestOptions().timeoutMs!);
    const key = this.#config.connection?.key;
    const codec = new MessageCodec(key === undefined ? undefined : await createAuthenticator(key));
    const transport = await factory.connect({ decode: (bytes) => codec.decode(bytes), logger });
    const session = new Session({
      transport,
      codec,
      logger,
      client: this.#options.client ?? '@hal/physical',
      heartbeatIntervalMs: () =>
        Math.max(
          5,
          this.#real(
            this.#options.heartbeatIntervalMs ?? Math.min(500, this.#robot.hostTimeoutMs / 4),
          ),
        ),
      reconnectIntervalMs: this.#options.reconnectIntervalMs ?? 1000,
      request: () => this.#requestOptions(),
      onReply: (cmd, data) => this.#observe(cmd, data),
      onStateChange: (state, reason) => this.#linkChanged(state, reason),
      onConnected: (hello, reconnect) => (reconnect ? this.#resync(hello) : undefined),
    });
    this.#transport = transport;
    this.#session = session;
    try {
      const hello = await session.open();
      this.#learn(hello);
      const status = await session.command('get_status', {});
      this.#tracker.anchor(status);
      this.#initialized = true;
      this.#camera?.start();
      this.#log.info('connected', { deviceId: hello.device_id, transport: transport.type });
    } catch (error) {
      session.close();
      await transport.close();
      this.#session = undefined;
      this.#transport = undefined;
      throw error;
    }
  }

  /** Stops the motors, closes the session and the link. Safe to call twice. */
  async cleanup(): Promise<void> {
    await this.#initializing?.catch(() => undefined);
    const session = this.#session;
    const transport = this.#transport;
    this.#initialized = false;
    this.#session = undefined;
    this.#transport = undefined;
    if (session !== undefined && session.state === 'connected') {
      await session.command('stop', {}, { attempts: 1 }).catch(() => undefined);
    }
    session?.close();
    await transport?.close();
    await this.#camera?.stop();
  }

  isReady(): boolean {
    return this.#initialized && this.#session?.state === 'connected';
  }

  getDeviceInfo(): DeviceInfo {
    const capabilities = [...(this.#identity?.capabilities ?? [])];
    if (this.#camera !== undefined) capabilities.push(CAPABILITIES.camera);
    return { id: this.#config.deviceId, type: 'v1-stepper-cube', mode: this.mode, capabilities };
  }

  /** What the robot reported in `hello` (undefined before `initialize()`). */
  get identity(): RobotIdentity | undefined {
    return this.#identity;
  }

  /** The robot configuration the HAL validates against (learned from the robot). */
  get robotConfig(): RobotConfig {
    return this.#robot;
  }

  /** The link's round-trip statistics. */
  transportStats(): TransportStats | undefined {
    return this.#transport?.stats();
  }

  /** The serial link's frame statistics (undefined on other links). */
  linkStats(): SerialLinkStats | undefined {
    const transport = this.#transport as
      (Transport & { linkStats?: () => SerialLinkStats }) | undefined;
    return transport?.linkStats?.();
  }

  /** The link state: `connected`, `lost` (reconnecting), `closed`, or `idle` before initialize. */
  get linkState(): SessionState {
    return this.#session?.state ?? 'idle';
  }

  /** Stops sending heartbeats, so the robot's host timeout can be seen to fire (for tests). */
  pauseHeartbeat(): void {
    this.#session?.pauseHeartbeat();
  }

  /** Sends heartbeats again. */
  resumeHeartbeat(): void {
    this.#session?.resumeHeartbeat();
  }

  /** Asks the robot for its status now (and updates the pose and safety state from it). */
  async refreshStatus(): Promise<StatusReply> {
    return await this.#command('get_status', {});
  }

  // -- internals -----------------------------------------------------------------------------

  #command<C extends Command>(cmd: C, params: RequestParams[C]): Promise<ReplyOf<C>> {
    const session = this.#session;
    if (session === undefined) {
      return Promise.reject(new HalError('NOT_READY', 'the HAL is not initialised'));
    }
    return session.command(cmd, params).catch((error: unknown) => {
      if (isHalError(error) && error.code === 'EMERGENCY_STOPPED') {
        // the robot latched on its own (a step-limit trip, another host): cache what it says
        this.#robotEstop = true;
        const robotDetails = error.details?.['robotDetails'] as Record<string, unknown> | undefined;
        this.#robotEstopReason = String(robotDetails?.['reason'] ?? 'emergency stop');
      }
      throw error;
    });
  }

  #learn(hello: HelloReply): void {
    this.#identity = {
      deviceId: hello.device_id,
      firmwareVersion: hello.firmware_version,
      protocolVersion: hello.protocol_version,
      auth: hello.auth,
      capabilities: hello.capabilities,
      config: hello.config,
    };
    this.#robot = deviceRobotConfig(this.#robot, hello.config);
    this.#tracker.setConfig(this.#robot);
  }

  #isEstopped(): boolean {
    return this.#robotEstop || this.#hostEstop !== undefined;
  }

  async #resync(hello: HelloReply): Promise<void> {
    this.#learn(hello);
    try {
      const status = await this.#command('get_status', {});
      if (this.#hostEstop !== undefined && !status.safety.estop) {
        // the stop never arrived, or the robot restarted and forgot it: stop it again
        await this.#command('estop', { reason: this.#hostEstop });
      }
      this.#log.info('reconnected', { sid: hello.sid, uptimeMs: status.uptime_ms });
    } catch (error) {
      this.#log.warn('status after reconnect failed', { error: String(error) });
    }
  }

  #linkChanged(state: SessionState, reason: string): void {
    this.#linkError = state === 'lost' ? `link lost: ${reason}` : undefined;
    if (state === 'lost') this.#log.warn('link lost', { reason });
  }

  /** Keeps the cached safety state and the pose in step with every reply. */
  #observe(cmd: string, data: Record<string, unknown>): void {
    switch (cmd) {
      case 'get_status': {
        const status = data as unknown as StatusReply;
        this.#lastStatus = status;
        this.#tracker.update(status);
        this.#robotEstop = status.safety.estop;
        this.#robotEstopReason = status.safety.estop ? status.safety.estop_reason : undefined;
        break;
      }
      case 'heartbeat':
        this.#robotEstop = data['estop'] === true;
        if (!this.#robotEstop) this.#robotEstopReason = undefined;
        break;
      case 'estop':
        this.#robotEstop = true;
        this.#robotEstopReason = String(data['estop_reason'] ?? '');
        this.#tracker.motionStopped();
        break;
      case 'reset_estop':
        this.#robotEstop = false;
        this.#robotEstopReason = undefined;
        this.#hostEstop = undefined;
        break;
      case 'stop':
        this.#tracker.updateCounters(Number(data['left_steps']), Number(data['right_steps']));
        break;
      case 'move_cm':
      case 'move_steps':
      case 'rotate_deg':
      case 'drive':
        this.#tracker.motionStarted(data as unknown as MotionReply);
        break;
    }
  }

  #requestOptions(): RequestOptions {
    const timeoutMs =
      this.#options.requestTimeoutMs ??
      Math.max(20, Math.min(DEFAULT_REPLY_TIMEOUT_MS, this.#real(this.#robot.hostTimeoutMs / 4)));
    const attempts =
      this.#options.attempts ??
      Math.max(
        DEFAULT_ATTEMPTS,
        Math.ceil((DEFAULT_REPLY_TIMEOUT_MS * DEFAULT_ATTEMPTS) / timeoutMs),
      );
    return { timeoutMs, attempts };
  }

  /** Real milliseconds for a span of robot time. */
  #real(robotMs: number): number {
    return robotMs / this.#timeScale;
  }

  /**
   * Waits until the robot reports motion `moveId` finished, polling `get_status`. Times out (and
   * stops the robot) `motionTimeoutMarginMs` after the planned duration.
   */
  async #awaitMotion(reply: MotionReply, plannedMs: number): Promise<StatusReply> {
    const margin = this.#options.motionTimeoutMarginMs ?? 2000;
    const started = performance.now();
    const deadline = started + this.#real(plannedMs) * 1.2 + margin;
    const poll = Math.max(2, this.#real(this.#options.pollIntervalMs ?? 100));
    let wait = Math.max(2, this.#real(plannedMs));
    for (;;) {
      await sleep(Math.min(wait, Math.max(0, deadline - performance.now())));
      wait = poll;
      const status = await this.#command('get_status', {});
      if (status.move_id === reply.move_id && status.move_outcome !== 'running') {
        switch (status.move_outcome) {
          case 'done':
            return status;
          case 'estop':
            throw new HalError(
              'EMERGENCY_STOPPED',
              'the motion was cut short by the emergency stop',
              {
                details: this.#motionDetails(status),
              },
            );
          case 'host_timeout':
            throw new HalError(
              'INTERRUPTED',
              'the robot stopped the motion: it heard nothing from the host for longer than its host timeout',
              { details: this.#motionDetails(status) },
            );
          default:
            throw new HalError(
              'INTERRUPTED',
              `the motion was ${status.move_outcome} before it finished`,
              {
                details: this.#motionDetails(status),
              },
            );
        }
      }
      if (status.move_id !== reply.move_id) {
        throw new HalError('INTERRUPTED', 'the motion was replaced by another motion', {
          details: this.#motionDetails(status),
        });
      }
      if (performance.now() >= deadline) {
        await this.#command('stop', {}).catch(() => undefined);
        throw new HalError(
          'TIMEOUT',
          `the robot did not report motion ${reply.move_id} finished within ${Math.round(deadline - started)} ms (planned ${plannedMs} ms); stopped it`,
          { details: { ...this.#motionDetails(status), plannedMs } },
        );
      }
    }
  }

  #motionDetails(status: StatusReply): Record<string, unknown> {
    return {
      moveId: status.move_id,
      outcome: status.move_outcome,
      leftSteps: status.move_left_steps,
      rightSteps: status.move_right_steps,
    };
  }

  /** Runs a motion command to completion; returns the result data. */
  async #move(
    cmd: 'move_cm' | 'rotate_deg',
    params: RequestParams['move_cm'] | RequestParams['rotate_deg'],
  ): Promise<Record<string, unknown>> {
    const reply: MotionReply =
      cmd === 'move_cm'
        ? await this.#command('move_cm', params as RequestParams['move_cm'])
        : await this.#command('rotate_deg', params as RequestParams['rotate_deg']);
    const planned = reply.duration_ms ?? 0;
    const status = planned > 0 ? await this.#awaitMotion(reply, planned) : undefined;
    const pose = this.#tracker.pose();
    return {
      moveId: reply.move_id,
      leftSteps: status?.move_left_steps ?? reply.left_steps ?? 0,
      rightSteps: status?.move_right_steps ?? reply.right_steps ?? 0,
      plannedDurationMs: planned,
      pose: { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw },
    };
  }

  #speedStepsPerS(mPerS: number | undefined): number | undefined {
    if (mPerS === undefined) return undefined;
    return Math.max(
      1,
      Math.min(this.#robot.maxSpeedStepsPerS, mPerS * 100 * stepsPerCm(this.#robot)),
    );
  }

  #makeLocomotion(): LocomotionInterface {
    const b = this.#boundary;
    const straight = (cm: number) => this.#move('move_cm', { left_cm: cm, right_cm: cm });
    return {
      moveForward: (distanceCm) =>
        b.call('moveForward', { distanceCm }, (p) => straight(p.distanceCm)),
      moveBackward: (distanceCm) =>
        b.call('moveBackward', { distanceCm }, (p) => straight(-p.distanceCm)),
      rotate: (direction, degrees) =>
        b.call('rotate', { direction, degrees }, (p) =>
          this.#move('rotate_deg', { degrees: p.direction === 'left' ? p.degrees : -p.degrees }),
        ),
      drive: (left, right, durationMs) =>
        b.call('drive', { left, right, durationMs }, async (p) => {
          const max = this.#robot.maxSpeedStepsPerS;
          const leftSps = Math.trunc((p.left / MAX_POWER) * max);
          const rightSps = Math.trunc((p.right / MAX_POWER) * max);
          const params: RequestParams['drive'] = { left_sps: leftSps, right_sps: rightSps };
          if (p.durationMs !== undefined)
            params.duration_ms = Math.max(1, Math.round(p.durationMs));
          const reply = await this.#command('drive', params);
          const data = {
            moveId: reply.move_id,
            leftSps: reply.left_sps ?? leftSps,
            rightSps: reply.right_sps ?? rightSps,
            speedClamped: reply.speed_clamped ?? false,
          };
          if (params.duration_ms === undefined || reply.running === false) {
            return { ...data, running: reply.running ?? false };
          }
          const status = await this.#awaitMotion(reply, params.duration_ms);
          return {
            ...data,
            running: false,
            leftSteps: status.move_left_steps,
            rightSteps: status.move_right_steps,
          };
        }),
      moveTo: (x, y, z, speed) =>
        b.call('moveTo', { x, y, z, speed }, async (p) => {
          const sps = this.#speedStepsPerS(p.speed);
          const withSpeed = <T extends object>(params: T): T =>
            sps === undefined ? params : { ...params, speed: sps };
          let pose = this.#tracker.pose();
          let dx = p.x - pose.position.x;
          let dy = p.y - pose.position.y;
          if (Math.hypot(dx, dy) < 1e-4) return { moves: 0, pose: this.#poseData() };
          let moves = 0;
          const turn = normalizeAngle(Math.atan2(dy, dx) - pose.rotation.yaw);
          const turnDeg = (turn * 180) / Math.PI;
          if (Math.abs(turnDeg) > 0.01) {
            await this.#move('rotate_deg', withSpeed({ degrees: turnDeg }));
            moves += 1;
          }
          // go straight, in pieces no longer than one command allows
          const maxCm = (this.#robot.maxStepsPerCommand - 1) / stepsPerCm(this.#robot);
          for (;;) {
            pose = this.#tracker.pose();
            dx = p.x - pose.position.x;
            dy = p.y - pose.position.y;
            // distance along the heading actually reached
            const along =
              (dx * Math.cos(pose.rotation.yaw) + dy * Math.sin(pose.rotation.yaw)) * 100;
            if (along < 0.01) break;
            const cm = Math.min(along, maxCm);
            await this.#move('move_cm', withSpeed({ left_cm: cm, right_cm: cm }));
            moves += 1;
            if (cm >= along) break;
          }
          return { moves, pose: this.#poseData() };
        }),
      stop: () =>
        b.call('stop', {}, async () => {
          const reply = await this.#command('stop', {});
          return { stopped: reply.stopped, pose: this.#poseData() };
        }),
      getPose: async (): Promise<Pose> => this.#tracker.pose(),
    };
  }

  #poseData(): Record<string, number> {
    const pose = this.#tracker.pose();
    return { x: pose.position.x, y: pose.position.y, yaw: pose.rotation.yaw };
  }

  #makeVision(): VisionInterface {
    const lacks = (what: string) =>
      Promise.reject(
        new HalError('NOT_IMPLEMENTED', `the V1 stepper cube has no ${what}`, {
          details: { capability: what },
        }),
      );
    return {
      captureFrame: async () => {
        if (this.#camera === undefined) {
          throw new HalError(
            'NOT_IMPLEMENTED',
            'no camera configured: set connection.cameraUrl to the ESP32-CAM address',
          );
        }
        return await this.#camera.captureFrame();
      },
      scan: () => lacks('range sensors'),
      getDistanceSensors: () => lacks('range sensors'),
      getLineSensors: () => lacks('line sensors'),
      getIMU: async (): Promise<IMUReading> => {
        const pose = this.#tracker.pose();
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: pose.velocity.angular },
          heading: pose.rotation.yaw,
          source: 'odometry',
        };
      },
    };
  }

  #makeCommunication(): CommunicationInterface {
    const b = this.#boundary;
    return {
      speak: (text, urgency) =>
        b.call('speak', { text, urgency }, async () => {
          throw new HalError('NOT_IMPLEMENTED', 'the V1 stepper cube has no speaker');
        }),
      playSound: (soundId) =>
        b.call('playSound', { soundId }, async () => {
          throw new HalError('NOT_IMPLEMENTED', 'the V1 stepper cube has no speaker');
        }),
      setLED: (r, g, bl, pattern) =>
        b.call('setLED', { r, g, b: bl, pattern }, async (p) => {
          const reply = await this.#command('set_led', {
            r: p.r,
            g: p.g,
            b: p.b,
            pattern: p.pattern ?? 'solid',
          });
          return { led: reply.led };
        }),
      log: (message, level = 'info') => {
        this.#robotLog[level](String(message), { deviceId: this.#config.deviceId });
      },
    };
  }

  #makeSafety(): SafetyInterface {
    const b = this.#boundary;
    return {
      emergencyStop: (reason) =>
        b.call('emergencyStop', { reason }, async (p) => {
          const reason = p.reason ?? 'emergency stop';
          this.#hostEstop = reason; // refuse motion at once, whatever the link does
          const reply = await this.#command('estop', { reason });
          return { estop: reply.estop, reason: reply.estop_reason };
        }),
      isEmergencyStopped: () => this.#isEstopped(),
      resetEmergencyStop: () =>
        b.call('resetEmergencyStop', {}, async () => {
          const reply = await this.#command('reset_estop', {});
          return { wasEmergencyStopped: reply.was_estopped };
        }),
      getSafetyStatus: (): SafetyStatus => {
        const errors: string[] = [];
        if (this.#linkError !== undefined) errors.push(this.#linkError);
        const trip = this.#lastStatus?.safety.last_trip;
        if (trip !== undefined) errors.push(`last trip: ${trip.reason} (${trip.detail})`);
        const status: SafetyStatus = {
          emergencyStopped: this.#isEstopped(),
          batteryLevel: 100,
          errors,
        };
        const reason = this.#robotEstopReason ?? this.#hostEstop;
        if (this.#isEstopped() && reason !== undefined) status.emergencyStopReason = reason;
        return status;
      },
    };
  }
}
