import {
  CAPABILITIES,
  ROBOT_PART_CAPABILITY,
  cameraModel,
  errorMessage,
  HalError,
  scoped,
  silentLogger,
} from '@hal/types';
import type {
  CameraModel,
  DeviceInfo,
  DriveDone,
  EmergencyStopDone,
  HALConfig,
  HALLogLevel,
  LedSetting,
  LitLed,
  MotionCommand,
  MotionDone,
  Pose,
  RobotConfig,
  RobotPart,
  RobotPort,
  SafetyStatus,
  ScopedLogger,
} from '@hal/types';
import { MjpegCamera } from '../camera/mjpeg.js';
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
import type { HalContext } from './context.js';
import { defaultTransport, initialRobotConfig, parsePhysicalConfig } from './from-config.js';
import { LinkTiming } from './link-timing.js';
import { PHYSICAL_HAL_DEFAULTS as DEFAULTS } from './options.js';
import type { PhysicalHALOptions, RobotIdentity } from './options.js';
import { SafetyCache } from './safety-cache.js';
import {
  notInitialised,
  wireDrive,
  wireEmergencyStop,
  wireMotion,
  wireResetEmergencyStop,
  wireStop,
} from './wire-motions.js';

/**
 * The V1 stepper cube over its wire session (protocol 1.1, docs/protocol.md) through a UDP or
 * serial transport, as a {@link RobotPort}: a motion resolves when `get_status` reports it
 * finished; the pose is dead-reckoned on the host from the robot's step counters, in a frame
 * anchored where the robot stood when the session opened (the origin, or `startPose`); the
 * e-stop latches on the host before it is sent. Over the mock transport (`mockTransport`) it
 * drives the mock robot: the same binding, another link. What only the cube has (the link's
 * statistics, its identity, calibration, heartbeats) is here too.
 */
export class WireBinding implements RobotPort {
  readonly mode = 'physical' as const;
  readonly captureFrame?: () => Promise<string>;

  readonly #config: HALConfig;
  readonly #options: PhysicalHALOptions;
  readonly #log: ScopedLogger;
  readonly #robotLog: ScopedLogger;
  readonly #timing: LinkTiming;
  readonly #camera: MjpegCamera | undefined;
  readonly #tracker: PoseTracker;
  readonly #safety = new SafetyCache();
  readonly #ctx: HalContext;
  readonly #configListeners: Array<() => void> = [];
  #robot: RobotConfig;
  #transport: Transport | undefined;
  #session: Session | undefined;
  #identity: RobotIdentity | undefined;
  /** A calibration applied in this binding's life ({@link applyCalibration}): wins over the source. */
  #calibration: WheelCalibration | undefined;
  /** The camera model from the robot's calibration (`hal calibrate camera`), once hello named it. */
  #calibratedCamera: CameraModel | undefined;

  constructor(config: HALConfig, options: PhysicalHALOptions = {}) {
    const parsed = parsePhysicalConfig(config);
    const timeScale = options.timeScale ?? DEFAULTS.timeScale;
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
    this.#robotLog = scoped(logger, 'hal:physical:log');
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
    const camera = this.#camera;
    if (camera !== undefined) this.captureFrame = () => camera.captureFrame();
    this.#ctx = {
      robot: () => this.#robot,
      tracker: this.#tracker,
      timing: this.#timing,
      safety: this.#safety,
      command: (cmd, params) => this.#command(cmd, params),
      safetyCommand: async (cmd, params) => {
        const session = this.#session;
        // no session yet (or any more): open() sends the host latch once one is open
        if (session === undefined || session.sid === undefined) return undefined;
        return await session.safetyCommand(cmd, params);
      },
      safetyEpoch: () => this.#session?.safetyEpoch ?? 0,
      interrupted: (epoch) =>
        this.#session?.interrupted(epoch) ?? new Promise<SafetyInterrupt>(() => undefined),
    };
  }

  // -- the robot port ------------------------------------------------------------------------

  /** Opens the link and the session, learns who the robot is and anchors the pose. */
  async open(): Promise<void> {
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
      client: this.#options.client ?? DEFAULTS.client,
      heartbeatIntervalMs: () => this.#timing.heartbeatMs(),
      reconnectIntervalMs: this.#options.reconnectIntervalMs ?? DEFAULTS.reconnectIntervalMs,
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
        // emergencyStop() was called before open() (or after a close): latch the robot too
        await session.command('estop', { reason: hostLatch });
      }
      await this.#calibrate(hello);
      this.#camera?.start();
      this.#log.info('connected', { deviceId: hello.device_id, transport: transport.type });
      if (hello.auth === 'none') {
        this.#log.warn(
          'the robot runs without authentication: anyone who reaches it can command it',
          { deviceId: hello.device_id },
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

  /** Stops the motors, closes the session and the link. Safe to call twice. */
  async close(): Promise<void> {
    const session = this.#session;
    const transport = this.#transport;
    this.#session = undefined;
    this.#transport = undefined;
    if (session !== undefined && session.state === 'connected') {
      await session
        .safetyCommand(
          'stop',
          {},
          {
            resendMs: DEFAULTS.safetyLane.resendMs,
            totalMs: DEFAULTS.cleanupStopMs,
          },
        )
        .catch(() => undefined);
    }
    session?.close();
    await transport?.close();
    await this.#camera?.stop();
  }

  isConnected(): boolean {
    return this.#session?.state === 'connected';
  }

  now(): number {
    return (this.#options.now ?? Date.now)();
  }

  config(): RobotConfig {
    return this.#robot;
  }

  deviceInfo(): DeviceInfo {
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

  /** The host's dead reckoning; `confirmed: false` while it is a prediction. */
  pose(): Pose {
    return this.#tracker.pose();
  }

  async motion(command: MotionCommand): Promise<MotionDone> {
    return await wireMotion(this.#ctx, command);
  }

  async drive(leftSps: number, rightSps: number, durationMs?: number): Promise<DriveDone> {
    return await wireDrive(this.#ctx, leftSps, rightSps, durationMs);
  }

  async stop(): Promise<boolean> {
    return await wireStop(this.#ctx);
  }

  /** Latches on the host first; before `open()` or after `close()` only the host latches. */
  async emergencyStop(reason: string): Promise<EmergencyStopDone> {
    return await wireEmergencyStop(this.#ctx, reason);
  }

  async resetEmergencyStop(): Promise<boolean> {
    return await wireResetEmergencyStop(this.#ctx);
  }

  isEmergencyStopped(): boolean {
    return this.#safety.isEstopped();
  }

  safetyStatus(): SafetyStatus {
    return this.#safety.status();
  }

  async setLed(led: LedSetting): Promise<LitLed> {
    return (await this.#command('set_led', led)).led;
  }

  log(message: string, level: HALLogLevel): void {
    this.#robotLog[level](message, { deviceId: this.#config.deviceId });
  }

  logRefused(refusal: { code?: string | undefined; error?: string | undefined }): void {
    // the scoped logger swallows its own failures, so this cannot throw either
    this.#robotLog.warn('log refused', { deviceId: this.#config.deviceId, ...refusal });
  }

  lacks(part: RobotPart): HalError {
    const message =
      part === 'camera'
        ? 'no camera configured: set connection.cameraUrl to the ESP32-CAM address'
        : `the V1 stepper cube has no ${part}`;
    return new HalError('NOT_IMPLEMENTED', message, {
      details: { capability: ROBOT_PART_CAPABILITY[part] },
    });
  }

  onConfigChanged(listener: () => void): void {
    this.#configListeners.push(listener);
  }

  // -- what only the cube has ----------------------------------------------------------------

  /** What the robot reported in `hello` (undefined before the session opened). */
  get identity(): RobotIdentity | undefined {
    return this.#identity;
  }

  /** The link's round-trip statistics. */
  transportStats(): TransportStats | undefined {
    return this.#transport?.stats();
  }

  /**
   * The wheel step counters and speeds the robot last reported (its status and stop replies, not
   * the host's prediction between them); undefined before the session read a status.
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

  /** The link state: `connected`, `lost` (reconnecting), `closed`, or `idle` before open. */
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
   * validation, and sends it again after every later hello (reconnects). Resolves the robot
   * configuration now in use; RANGE_EXCEEDED naming the field when a value is outside the
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
    if (session === undefined) return Promise.reject(notInitialised());
    // a refusal reaches the safety cache through the session's onCommandFailed
    return session.command(cmd, params);
  }

  /** The camera model of the config: its `camera` settings over V1's. */
  #configuredCamera(): CameraModel {
    const settings = Object.fromEntries(
      Object.entries(this.#config.camera ?? {}).filter(([, value]) => value !== undefined),
    ) as Partial<CameraModel>;
    return cameraModel(settings);
  }

  /** The first hello's timing: resent as any request is, for `connectTimeoutMs` if given. */
  #helloOptions(): RequestOptions | undefined {
    const connectMs = this.#options.connectTimeoutMs;
    if (connectMs === undefined) return undefined;
    const timeoutMs = Math.min(
      this.#timing.request().timeoutMs ?? DEFAULTS.replyTimeoutMs,
      connectMs,
    );
    return { timeoutMs, attempts: Math.max(1, Math.floor(connectMs / timeoutMs)) };
  }

  /** How a stop is resent now: shorter once the link is known dead (see LinkTiming.stopLane). */
  #safetyLane(): SafetyLaneTiming {
    const silentMs = performance.now() - this.#tracker.heardAt;
    const dead =
      this.#session?.state === 'lost' || silentMs > this.#timing.real(this.#robot.hostTimeoutMs);
    return this.#timing.stopLane(dead);
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
    for (const listener of this.#configListeners) listener();
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
    if (session === undefined) throw notInitialised();
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
      this.#log.warn('status after reconnect failed', { error: errorMessage(error) });
    }
    try {
      // a restarted robot has forgotten its calibration (the e-stop went first, above)
      await this.#calibrate(hello);
    } catch (error) {
      this.#log.error('calibration after reconnect failed', { error: errorMessage(error) });
    }
  }

  #linkChanged(state: SessionState, reason: string): void {
    this.#safety.linkChanged(state, reason);
    this.#tracker.linkChanged(state === 'connected');
    if (state === 'lost') this.#log.warn('link lost', { reason });
  }
}
