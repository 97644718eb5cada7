import { CAPABILITIES, cameraModel, HalBoundary, HalError } from '@hal/types';
import type {
  CameraModel,
  CommunicationInterface,
  DeviceInfo,
  HALConfig,
  HardwareAbstractionLayer,
  LocomotionInterface,
  RobotConfig,
  SafetyInterface,
  VisionInterface,
} from '@hal/types';
import { MjpegCamera } from '../camera/mjpeg.js';
import { scoped, silentLogger } from '@hal/types';
import type { ScopedLogger } from '@hal/types';
import { PoseTracker } from '../pose-tracker.js';
import type { ReportedSteps } from '../pose-tracker.js';
import { createAuthenticator } from '../protocol/auth.js';
import { MessageCodec } from '../protocol/codec.js';
import { robotConfigFromDevice } from '../protocol/device-config.js';
import type {
  Command,
  HelloReply,
  ReplyOf,
  RequestParams,
  StatusReply,
} from '../protocol/schemas.js';
import { DEFAULT_SAFETY_LANE } from '../safety-lane.js';
import type { SafetyInterrupt, SafetyLaneTiming } from '../safety-lane.js';
import { Session } from '../session.js';
import type { SessionState } from '../session.js';
import type {
  RequestOptions,
  SerialLinkStats,
  Transport,
  TransportStats,
} from '../transport/transport.js';
import { robotCalibration, sendCalibration } from './calibration.js';
import type { WheelCalibration } from './calibration.js';
import { createCommunication } from './communication.js';
import type { HalContext } from './context.js';
import { defaultTransport, initialRobotConfig, parsePhysicalConfig } from './from-config.js';
import { LinkTiming } from './link-timing.js';
import { createLocomotion } from './locomotion.js';
import type { PhysicalHALOptions, RobotIdentity } from './options.js';
import { SafetyCache } from './safety-cache.js';
import { createSafety } from './safety.js';
import { createVision } from './vision.js';

/** How long a stop is resent once the link is known dead, ms. */
const DEAD_LINK_STOP_MS = 300;

/**
 * The HAL of the physical V1 stepper cube, spoken to over protocol 1.0 (docs/protocol.md) through
 * a UDP or serial transport. Every public call goes through the shared {@link HalBoundary}; a
 * motion resolves when the robot reports it finished; the pose is dead-reckoned on the host from
 * the robot's step counters, in a frame anchored where the robot stood at `initialize()` (the origin, or `startPose`).
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
  readonly #timing: LinkTiming;
  readonly #camera: MjpegCamera | undefined;
  readonly #tracker: PoseTracker;
  readonly #safety = new SafetyCache();
  readonly #boundary: HalBoundary;
  #robot: RobotConfig;
  #transport: Transport | undefined;
  #session: Session | undefined;
  #identity: RobotIdentity | undefined;
  #initialized = false;
  #initializing: Promise<void> | undefined;
  /** A calibration applied in this HAL's life ({@link applyCalibration}): wins over the source. */
  #calibration: WheelCalibration | undefined;
  /** The camera model from the robot's calibration (`hal calibrate camera`), once hello named it. */
  #calibratedCamera: CameraModel | undefined;

  constructor(config: HALConfig, options: PhysicalHALOptions = {}) {
    const parsed = parsePhysicalConfig(config);
    const timeScale = options.timeScale ?? 1;
    if (!(timeScale > 0) || !Number.isFinite(timeScale)) {
      throw new HalError('INVALID_PARAMETER', `"timeScale" must be a finite number > 0`);
    }
    const start = options.startPose;
    if (start !== undefined && ![start.x, start.y, start.yaw].every(Number.isFinite)) {
      throw new HalError(
        'INVALID_PARAMETER',
        `"startPose" must be finite metres and radians (got x ${start.x}, y ${start.y}, yaw ${start.yaw})`,
      );
    }
    this.#config = parsed;
    this.#options = options;
    this.#timing = new LinkTiming(options, timeScale, () => this.#robot);
    const logger = options.logger ?? silentLogger;
    this.#log = scoped(logger, 'hal:physical');
    this.#robot = initialRobotConfig(parsed);
    this.#tracker = new PoseTracker(this.#robot, () => performance.now(), timeScale);
    const cameraUrl = parsed.connection?.cameraUrl;
    const cameraToken = parsed.connection?.cameraToken;
    this.#camera =
      cameraUrl === undefined
        ? undefined
        : new MjpegCamera({
            url: cameraUrl,
            logger,
            ...(cameraToken === undefined ? {} : { token: cameraToken }),
          });
    const boundary = new HalBoundary({
      mode: this.mode,
      config: () => this.#robot,
      isEmergencyStopped: () => this.#safety.isEstopped(),
      // initialised is enough here: a lost link is reported by the call itself, as NOT_CONNECTED
      isReady: () => this.#initialized,
      now: options.now ?? Date.now,
    });
    this.#boundary = boundary;
    const ctx: HalContext = {
      boundary,
      robot: () => this.#robot,
      tracker: this.#tracker,
      timing: this.#timing,
      safety: this.#safety,
      command: (cmd, params) => this.#command(cmd, params),
      safetyCommand: async (cmd, params) => {
        const session = this.#session;
        // no session yet (or any more): initialize() sends the host latch once one is open
        if (session === undefined || session.sid === undefined) return undefined;
        return await session.safetyCommand(cmd, params);
      },
      safetyEpoch: () => this.#session?.safetyEpoch ?? 0,
      interrupted: (epoch) =>
        this.#session?.interrupted(epoch) ?? new Promise<SafetyInterrupt>(() => undefined),
    };
    this.locomotion = createLocomotion(ctx);
    this.vision = createVision(ctx, this.#camera);
    const robotLog = scoped(logger, 'hal:physical:log');
    this.communication = createCommunication(ctx, robotLog, parsed.deviceId);
    this.safety = createSafety(ctx);
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
      this.#options.transport ?? defaultTransport(this.#config, this.#timing.request().timeoutMs!);
    const key = this.#config.connection?.key;
    const codec = new MessageCodec(key === undefined ? undefined : await createAuthenticator(key));
    const transport = await factory.connect({ decode: (bytes) => codec.decode(bytes), logger });
    const session = new Session({
      transport,
      codec,
      logger,
      client: this.#options.client ?? '@hal/physical',
      heartbeatIntervalMs: () => this.#timing.heartbeatMs(),
      reconnectIntervalMs: this.#options.reconnectIntervalMs ?? 1000,
      request: () => this.#timing.request(),
      safetyLane: () => this.#safetyLane(),
      onReply: (cmd, data) => {
        this.#tracker.observe(cmd, data);
        this.#safety.observe(cmd, data);
      },
      onCommandFailed: (error) => this.#safety.refused(error),
      onStateChange: (state, reason) => this.#linkChanged(state, reason),
      onConnected: (hello, reconnect) => (reconnect ? this.#resync(hello) : undefined),
    });
    this.#transport = transport;
    this.#session = session;
    try {
      const hello = await session.open(this.#helloOptions());
      this.#learn(hello);
      const status = await session.command('get_status', {});
      this.#tracker.anchor(status, this.#options.startPose);
      const hostLatch = this.#safety.hostLatch;
      if (hostLatch !== undefined && !status.safety.estop) {
        // emergencyStop() was called before initialize() (or after a cleanup): latch the robot too
        await session.command('estop', { reason: hostLatch });
      }
      await this.#calibrate(hello);
      this.#initialized = true;
      this.#camera?.start();
      this.#log.info('connected', { deviceId: hello.device_id, transport: transport.type });
      if (hello.auth === 'none') {
        this.#log.warn(
          'the robot runs without authentication: anyone who reaches it can command it',
          {
            deviceId: hello.device_id,
          },
        );
      }
    } catch (error) {
      session.close();
      await transport.close();
      this.#session = undefined;
      this.#transport = undefined;
      throw error;
    }
  }

  /** The first hello's timing: resent as any request is, for `connectTimeoutMs` if given. */
  #helloOptions(): RequestOptions | undefined {
    const connectMs = this.#options.connectTimeoutMs;
    if (connectMs === undefined) return undefined;
    const timeoutMs = Math.min(this.#timing.request().timeoutMs ?? 500, connectMs);
    return { timeoutMs, attempts: Math.max(1, Math.floor(connectMs / timeoutMs)) };
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
      await session
        .safetyCommand('stop', {}, { resendMs: DEFAULT_SAFETY_LANE.resendMs, totalMs: 500 })
        .catch(() => undefined);
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
    const info: DeviceInfo = {
      id: this.#config.deviceId,
      type: 'v1-stepper-cube',
      mode: this.mode,
      capabilities,
    };
    if (this.#camera === undefined) return info;
    capabilities.push(CAPABILITIES.camera);
    // the calibrated model, else the configured one (V1's where the config says nothing)
    return { ...info, camera: this.#calibratedCamera ?? this.#configuredCamera() };
  }

  /** The camera model of the config: its `camera` settings over V1's. */
  #configuredCamera(): CameraModel {
    const settings = Object.fromEntries(
      Object.entries(this.#config.camera ?? {}).filter(([, value]) => value !== undefined),
    ) as Partial<CameraModel>;
    return cameraModel(settings);
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

  /**
   * The wheel step counters and speeds the robot last reported (its status and stop replies, not
   * the host's prediction between them); undefined before `initialize()` has read a status.
   */
  reportedSteps(): ReportedSteps | undefined {
    return this.#tracker.reported();
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

  /**
   * Sends `calibration` to the robot now (`set_config`), uses it for the host's odometry and
   * validation, and sends it again after every later hello of this HAL (reconnects). Resolves the
   * robot configuration now in use; RANGE_EXCEEDED naming the field when a value is outside the
   * firmware's range (nothing is sent), the robot's own code when it refuses.
   */
  async applyCalibration(calibration: WheelCalibration): Promise<RobotConfig> {
    const deviceId = this.#identity?.deviceId ?? this.#config.deviceId;
    const config = await sendCalibration(
      (params) => this.#command('set_config', params),
      calibration,
      deviceId,
    );
    this.#calibration = calibration;
    this.#useDeviceConfig(config);
    return this.#robot;
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
    // a refusal reaches the safety cache through the session's onCommandFailed
    return session.command(cmd, params);
  }

  /**
   * Resend every 20 ms, within the same total budget as any other request but never longer than
   * the robot's host timeout: a robot that hears nothing from the host for that long stops by
   * itself, so a longer wait only delays the news that it could not be told. Once the link is
   * known dead (lost, or the robot silent for its host timeout) one short try is all there is.
   */
  #safetyLane(): SafetyLaneTiming {
    if (this.#options.safetyLane !== undefined) return this.#options.safetyLane;
    const { timeoutMs, attempts } = this.#timing.request();
    const requestMs =
      timeoutMs === undefined || attempts === undefined
        ? DEFAULT_SAFETY_LANE.totalMs
        : timeoutMs * attempts;
    const hostTimeoutMs = this.#timing.real(this.#robot.hostTimeoutMs);
    const silentMs = performance.now() - this.#tracker.heardAt;
    const dead = this.#session?.state === 'lost' || silentMs > hostTimeoutMs;
    const totalMs = Math.min(requestMs, dead ? DEAD_LINK_STOP_MS : Math.max(hostTimeoutMs, 100));
    return { resendMs: DEFAULT_SAFETY_LANE.resendMs, totalMs };
  }

  #learn(hello: HelloReply): void {
    this.#identity = {
      deviceId: hello.device_id,
      firmwareVersion: hello.firmware_version,
      protocolVersion: hello.protocol_version,
      auth: hello.auth === 'hmac-sha256',
      authScheme: hello.auth,
      capabilities: hello.capabilities,
      config: hello.config,
    };
    this.#useDeviceConfig(hello.config);
  }

  #useDeviceConfig(config: HelloReply['config']): void {
    this.#robot = robotConfigFromDevice(this.#robot, config);
    this.#tracker.setConfig(this.#robot);
    this.#boundary.schemas(); // the call schemas for this robot now, not on the first call
  }

  /** Sends the robot's calibration, if there is one, once a hello opened the session. */
  async #calibrate(hello: HelloReply): Promise<void> {
    let calibration = this.#calibration;
    if (calibration === undefined) {
      const found = robotCalibration(await this.#options.calibration?.(hello.device_id));
      if (found.camera !== undefined) this.#calibratedCamera = cameraModel(found.camera);
      calibration = found.wheels;
    }
    if (calibration === undefined) return;
    const session = this.#session;
    if (session === undefined) throw new HalError('NOT_READY', 'the HAL is not initialised');
    const config = await sendCalibration(
      (params) => session.command('set_config', params),
      calibration,
      hello.device_id,
    );
    this.#useDeviceConfig(config);
    this.#log.info('calibration sent', {
      deviceId: hello.device_id,
      wheelDiameterCm: config.wheel_diameter_cm,
      wheelBaseCm: config.wheel_base_cm,
    });
  }

  async #resync(hello: HelloReply): Promise<void> {
    this.#learn(hello);
    try {
      const status = await this.#command('get_status', {});
      const hostLatch = this.#safety.hostLatch;
      if (hostLatch !== undefined && !status.safety.estop) {
        // the stop never arrived, or the robot restarted and forgot it: stop it again
        await this.#command('estop', { reason: hostLatch });
      }
      this.#log.info('reconnected', { sid: hello.sid, uptimeMs: status.uptime_ms });
    } catch (error) {
      this.#log.warn('status after reconnect failed', { error: String(error) });
    }
    try {
      // a restarted robot has forgotten its calibration (the e-stop went first, above)
      await this.#calibrate(hello);
    } catch (error) {
      this.#log.error('calibration after reconnect failed', { error: String(error) });
    }
  }

  #linkChanged(state: SessionState, reason: string): void {
    this.#safety.linkChanged(state, reason);
    this.#tracker.linkChanged(state === 'connected');
    if (state === 'lost') this.#log.warn('link lost', { reason });
  }
}
