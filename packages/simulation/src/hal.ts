import { normalizeAngle } from '@hal/kinematics';
import {
  CAPABILITIES,
  HALConfigSchema,
  HalBoundary,
  HalError,
  hasCapability,
  robotConfig,
  stepsPerCm,
  V1_ROBOT,
} from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALConfig,
  HALLogLevel,
  HardwareAbstractionLayer,
  LocomotionInterface,
  Pose,
  RobotConfig,
  SafetyInterface,
  SafetyStatus,
  VisionInterface,
} from '@hal/types';
import { renderRobotView } from './camera.js';
import type { CameraOptions } from './camera.js';
import { encodeJpeg, jpegDataUrl } from './jpeg.js';
import type { MotionHandle, MotionReport, SimRobot } from './robot.js';
import { readDistanceSensors, readImu, scanAround } from './sensors.js';
import type { RangeSensorOptions } from './sensors.js';
import { Emitter, World } from './world.js';

/** Renders a robot's camera frame as a `data:image/jpeg;base64,...` URL. */
export type FrameSource = (world: World, robot: SimRobot) => Promise<string>;

/** How the HAL waits for a motion to end. */
export type SimulationClock =
  /** The HAL advances the world's clock itself until the motion ends: faster than real time. */
  | 'fast'
  /** A real-time ticker advances the clock (`world.startRealtime`, started by the HAL if off). */
  | 'realtime'
  /** Someone else steps the world (`world.step()`); the HAL only waits. */
  | 'manual';

/** What the simulated robot has besides wheels, an LED and an e-stop. */
export interface SimulatedFeatures {
  /** A camera (`captureFrame`). Default true. */
  camera?: boolean;
  /** Range sensors front/left/right (`getDistanceSensors`, `scan`). Default true. */
  rangeSensors?: boolean;
  /** An IMU (`getIMU` with source 'simulation'; without one, heading from odometry). Default true. */
  imu?: boolean;
  /** A speaker (`speak`, `playSound` emit events). Default false, like the V1 robot. */
  speaker?: boolean;
}

/** Something the HAL's communication subsystem did, for a UI to show. */
export type CommunicationEvent =
  | { type: 'led'; r: number; g: number; b: number; pattern: 'solid' | 'blink' | 'pulse' }
  | { type: 'speak'; text: string; urgency: 'info' | 'warning' | 'alert' }
  | { type: 'sound'; soundId: string }
  | { type: 'log'; message: string; level: HALLogLevel; atMs: number };

/** Everything a {@link SimulationHAL} reports as it happens. */
export interface SimulationHALEvents extends Record<string, unknown> {
  communication: CommunicationEvent;
  /** A motion started (firmware command issued). */
  motionStarted: MotionReport;
  /** A motion ended, with its outcome. */
  motionFinished: MotionReport;
  /** The emergency stop latched or cleared. */
  safety: SafetyStatus;
}

/** A logger the HAL writes to (never the console). */
export interface SimLogger {
  debug(message: string): void;
  info(message: string): void;
  warn(message: string): void;
  error(message: string): void;
}

export interface SimulationHALOptions {
  /** The world to live in; default a new world on the `empty` map. */
  world?: World;
  /** The id of an existing robot in `world` to drive; default a new robot is added. */
  robotId?: string;
  /** Geometry and limits of a newly added robot; default the V1 robot. */
  robot?: Partial<RobotConfig>;
  /** Start pose of a newly added robot; default the map's start. */
  start?: { x: number; y: number; yaw: number };
  /** How motions are waited for. Default 'fast'. */
  clock?: SimulationClock;
  /** Speed of the ticker the HAL starts in 'realtime' mode. Default 1. */
  realtimeSpeed?: number;
  /** 'manual' mode: fail a motion with TIMEOUT when the clock has not moved for this long, ms. Default 60000. */
  manualTimeoutMs?: number;
  /** 'realtime' mode: fail a motion with TIMEOUT when the ticker has stalled this long, ms. Default 5000. */
  stallTimeoutMs?: number;
  /** Extra features of the simulated robot. */
  features?: SimulatedFeatures;
  /** Range sensor model. */
  rangeSensors?: RangeSensorOptions;
  /** Camera model of the built-in software renderer. */
  camera?: CameraOptions;
  /** Renders frames another way (the browser demo uses Three.js). */
  frameSource?: FrameSource;
  /** Device id reported by `getDeviceInfo`. Default `sim-` + the robot id. */
  deviceId?: string;
  logger?: SimLogger;
}

const SILENT: SimLogger = {
  debug: () => undefined,
  info: () => undefined,
  warn: () => undefined,
  error: () => undefined,
};

const defaultFrameSource =
  (options: CameraOptions): FrameSource =>
  async (world, robot) =>
    jpegDataUrl(await encodeJpeg(renderRobotView(world, robot, options)));

/**
 * The HAL of a simulated robot. Each call is mapped to the firmware command a PhysicalHAL sends
 * (see docs/simulation.md) and executed by a {@link SimRobot} that moves as the firmware does.
 */
export class SimulationHAL implements HardwareAbstractionLayer {
  readonly mode = 'simulation' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  readonly world: World;
  readonly events = new Emitter<SimulationHALEvents>();

  readonly #robotId: string;
  readonly #clock: SimulationClock;
  readonly #options: SimulationHALOptions;
  readonly #features: Required<SimulatedFeatures>;
  readonly #boundary: HalBoundary;
  readonly #logger: SimLogger;
  readonly #frameSource: FrameSource;
  #ready = false;
  #startedTicker = false;
  readonly #logs: string[] = [];

  constructor(options: SimulationHALOptions = {}) {
    this.#options = options;
    this.world = options.world ?? new World();
    this.#clock = options.clock ?? 'fast';
    this.#logger = options.logger ?? SILENT;
    this.#features = {
      camera: options.features?.camera ?? true,
      rangeSensors: options.features?.rangeSensors ?? true,
      imu: options.features?.imu ?? true,
      speaker: options.features?.speaker ?? false,
    };
    this.#frameSource = options.frameSource ?? defaultFrameSource(options.camera ?? {});
    if (options.robotId !== undefined) {
      this.#robotId = this.world.robot(options.robotId).id;
    } else {
      const added = this.world.addRobot({
        config: options.robot === undefined ? V1_ROBOT : robotConfig(options.robot),
        ...(options.start === undefined ? {} : { start: options.start }),
      });
      this.#robotId = added.id;
    }
    this.#boundary = new HalBoundary({
      mode: this.mode,
      config: () => this.robot.config,
      isEmergencyStopped: () => this.robot.emergencyStopped,
      isReady: () => this.#ready,
      now: () => this.world.nowUs / 1000,
    });
    this.locomotion = this.#makeLocomotion();
    this.vision = this.#makeVision();
    this.communication = this.#makeCommunication();
    this.safety = this.#makeSafety();
  }

  /**
   * Builds a SimulationHAL from the shared {@link HALConfig} (the way PhysicalHAL is built):
   * `mode` must be 'simulation'; `simulator` may be the {@link World} to join (default a new
   * one); `robot` overrides the V1 geometry and limits; `deviceId` names the device; and
   * `capabilities`, when given, chooses the simulated features (camera, range sensors, IMU,
   * speaker) by their capability strings. Throws INVALID_PARAMETER on a bad configuration.
   */
  static fromConfig(config: HALConfig, options: SimulationHALOptions = {}): SimulationHAL {
    const parsed = HALConfigSchema.safeParse(config);
    if (!parsed.success) {
      const issue = parsed.error.issues[0];
      const where = issue?.path.map(String).join('.') || 'config';
      throw new HalError('INVALID_PARAMETER', `HALConfig: "${where}" ${issue?.message ?? ''}`, {
        details: { parameter: where },
      });
    }
    const c = parsed.data;
    if (c.mode !== 'simulation') {
      throw new HalError(
        'INVALID_PARAMETER',
        `HALConfig: "mode" must be "simulation" for a SimulationHAL, got "${c.mode}"`,
        { details: { parameter: 'mode' } },
      );
    }
    if (c.simulator !== undefined && !(c.simulator instanceof World)) {
      throw new HalError('INVALID_PARAMETER', 'HALConfig: "simulator" must be a World', {
        details: { parameter: 'simulator' },
      });
    }
    const caps = c.capabilities;
    const features: SimulatedFeatures =
      caps === undefined
        ? (options.features ?? {})
        : {
            camera: hasCapability(caps, CAPABILITIES.camera),
            rangeSensors: hasCapability(caps, CAPABILITIES.rangeSensors),
            imu: hasCapability(caps, CAPABILITIES.imu),
            speaker: hasCapability(caps, CAPABILITIES.speaker),
          };
    return new SimulationHAL({
      ...options,
      ...(c.simulator instanceof World ? { world: c.simulator } : {}),
      ...(c.robot === undefined
        ? {}
        : {
            robot: Object.fromEntries(
              Object.entries(c.robot).filter(([, v]) => v !== undefined),
            ) as Partial<RobotConfig>,
          }),
      deviceId: c.deviceId,
      features,
    });
  }

  /** The simulated robot this HAL drives (looked up by id: a map change re-creates it). */
  get robot(): SimRobot {
    return this.world.robot(this.#robotId);
  }

  /** Messages passed to `communication.log`, oldest first (the last 1000). */
  get logs(): readonly string[] {
    return this.#logs;
  }

  async initialize(): Promise<void> {
    if (this.#clock === 'realtime' && this.world.realtimeSpeed === 0) {
      this.world.startRealtime({ speed: this.#options.realtimeSpeed ?? 1 });
      this.#startedTicker = true;
    }
    // PhysicalHAL opens a session with `hello`, which resets the robot's distance accumulators.
    this.robot.hello();
    this.#ready = true;
  }

  async cleanup(): Promise<void> {
    if (!this.#ready) return;
    this.#ready = false;
    this.world.robots.find((r) => r.id === this.#robotId)?.stop();
    if (this.#startedTicker) this.world.stopRealtime();
    this.#startedTicker = false;
  }

  isReady(): boolean {
    return this.#ready;
  }

  getDeviceInfo(): DeviceInfo {
    const caps: string[] = [
      CAPABILITIES.differentialDrive,
      `locomotion.stepper:v1.0:steps_per_rev=${this.robot.config.stepsPerRevolution}`,
      CAPABILITIES.led,
      CAPABILITIES.emergencyStop,
      'safety.host_timeout:v1.0',
    ];
    if (this.#features.camera) caps.push(CAPABILITIES.camera);
    if (this.#features.rangeSensors) caps.push(CAPABILITIES.rangeSensors);
    if (this.#features.imu) caps.push(CAPABILITIES.imu);
    if (this.#features.speaker) caps.push(CAPABILITIES.speaker, CAPABILITIES.sound);
    return {
      id: this.#options.deviceId ?? `sim-${this.#robotId}`,
      type: 'v1-stepper-cube',
      mode: this.mode,
      capabilities: caps,
    };
  }

  /**
   * Simulates the host going silent (no heartbeats between commands): a running motion stops
   * after the robot's host timeout, as the firmware's does. `false` makes the host talk again.
   */
  simulateHostSilence(silent: boolean): void {
    this.robot.setHostSilent(silent);
  }

  // ---- waiting for motions ------------------------------------------------------------------

  /** Waits for a motion to end and turns its outcome into the call's data, or throws. */
  async #await(handle: MotionHandle): Promise<MotionReport> {
    const report = handle.report;
    this.events.emit('motionStarted', { ...report });
    const planned = Number.isFinite(report.durationUs) ? report.durationUs : 0;
    const robot = this.robot;
    if (this.#clock === 'fast') {
      // The motion's own plan bounds the wait; the margin covers one tick and rounding.
      const limit = planned + 1_000_000;
      this.world.advanceUntil(() => report.outcome !== 'running', limit);
    } else {
      await this.#waitForClock(report, handle.finished, planned);
    }
    if (report.outcome === 'running') {
      robot.stop();
      throw new HalError(
        'TIMEOUT',
        `motion ${report.moveId} did not finish within its planned ${Math.ceil(planned / 1000)} ms (simulated time at ${Math.round(this.world.nowUs / 1000)} ms)`,
        { details: { moveId: report.moveId, plannedMs: Math.ceil(planned / 1000) } },
      );
    }
    this.events.emit('motionFinished', { ...report });
    if (report.outcome === 'done') return report;
    if (report.outcome === 'collision' && report.contact !== undefined) {
      const c = report.contact;
      throw new HalError(
        'COLLISION',
        `the robot touched ${c.robotId === undefined ? `a ${c.role}` : `robot "${c.robotId}"`} at (${c.point.x.toFixed(3)}, ${c.point.y.toFixed(3)}) m and stopped`,
        { details: { contact: c, pose: this.#poseData(), moveId: report.moveId } },
      );
    }
    throw new HalError('INTERRUPTED', `motion ${report.moveId} ended early: ${report.outcome}`, {
      details: { outcome: report.outcome, moveId: report.moveId, pose: this.#poseData() },
    });
  }

  /**
   * Waits for a motion that someone else's clock drives. Gives up when simulated time passes the
   * planned end by a second, or when the clock has not moved for the stall timeout (wall time).
   */
  async #waitForClock(
    report: MotionReport,
    finished: Promise<MotionReport>,
    plannedUs: number,
  ): Promise<void> {
    const stallMs =
      this.#clock === 'manual'
        ? (this.#options.manualTimeoutMs ?? 60_000)
        : (this.#options.stallTimeoutMs ?? 5000);
    const deadlineUs = report.startedUs + plannedUs + 1_000_000;
    let seenUs = this.world.nowUs;
    let seenAt = Date.now();
    let timer: ReturnType<typeof setInterval> | undefined;
    await Promise.race([
      finished,
      new Promise<void>((resolve) => {
        timer = setInterval(() => {
          const now = this.world.nowUs;
          if (now !== seenUs) {
            seenUs = now;
            seenAt = Date.now();
          }
          if (now > deadlineUs || Date.now() - seenAt > stallMs) resolve();
        }, 10);
      }),
    ]);
    clearInterval(timer);
  }

  #poseData(): Record<string, number> {
    const r = this.robot;
    return { x: r.x, y: r.y, yaw: r.yaw };
  }

  #motionData(report: MotionReport): Record<string, unknown> {
    return {
      moveId: report.moveId,
      leftSteps: report.doneLeft,
      rightSteps: report.doneRight,
      plannedDurationMs: Math.ceil(report.durationUs / 1000),
      pose: this.#poseData(),
    };
  }

  /** m/s along the ground to master-wheel steps/s, within 1..top speed (undefined: top speed). */
  #wheelSpeed(speedMPerS: number | undefined): number | undefined {
    if (speedMPerS === undefined) return undefined;
    const config = this.robot.config;
    return Math.max(1, Math.min(config.maxSpeedStepsPerS, speedMPerS * 100 * stepsPerCm(config)));
  }

  // ---- subsystems -----------------------------------------------------------------------------

  #makeLocomotion(): LocomotionInterface {
    const b = this.#boundary;
    const straight = async (cm: number): Promise<Record<string, unknown>> => {
      const report = await this.#await(this.robot.moveCm(cm, cm));
      return this.#motionData(report);
    };
    return {
      drive: (left, right, durationMs) =>
        b.call('drive', { left, right, durationMs }, async (p) => {
          const max = this.robot.config.maxSpeedStepsPerS;
          const leftSps = Math.trunc((p.left / 255) * max);
          const rightSps = Math.trunc((p.right / 255) * max);
          const ms = p.durationMs === undefined ? undefined : Math.max(1, Math.round(p.durationMs));
          const handle = this.robot.drive(leftSps, rightSps, ms);
          if (handle === undefined) {
            return { leftSps, rightSps, speedClamped: false, running: false };
          }
          const data = {
            moveId: handle.report.moveId,
            leftSps: handle.report.leftSps,
            rightSps: handle.report.rightSps,
            speedClamped: handle.report.speedClamped,
          };
          if (ms === undefined) {
            this.events.emit('motionStarted', { ...handle.report });
            void handle.finished.then((r) => this.events.emit('motionFinished', { ...r }));
            return { ...data, running: true };
          }
          const report = await this.#await(handle);
          return {
            ...data,
            running: false,
            leftSteps: report.doneLeft,
            rightSteps: report.doneRight,
          };
        }),
      moveTo: (x, y, z, speed) =>
        b.call('moveTo', { x, y, z, speed }, async (p) => {
          // The same commands PhysicalHAL sends: turn toward the point, then straight moves
          // along the heading reached, each no longer than one command allows.
          const robot = this.robot;
          const sps = this.#wheelSpeed(p.speed);
          let dx = p.x - robot.x;
          let dy = p.y - robot.y;
          if (Math.hypot(dx, dy) < 1e-4) return { moves: 0, pose: this.#poseData() };
          let moves = 0;
          const turnDeg = (normalizeAngle(Math.atan2(dy, dx) - robot.yaw) * 180) / Math.PI;
          if (Math.abs(turnDeg) > 0.01) {
            await this.#await(robot.rotateDeg(turnDeg, sps));
            moves += 1;
          }
          const maxCm = (robot.config.maxStepsPerCommand - 1) / stepsPerCm(robot.config);
          for (;;) {
            dx = p.x - robot.x;
            dy = p.y - robot.y;
            const along = (dx * Math.cos(robot.yaw) + dy * Math.sin(robot.yaw)) * 100;
            if (along < 0.01) break;
            const cm = Math.min(along, maxCm);
            await this.#await(robot.moveCm(cm, cm, sps));
            moves += 1;
            if (cm >= along) break;
          }
          return { moves, pose: this.#poseData() };
        }),
      rotate: (direction, degrees) =>
        b.call('rotate', { direction, degrees }, async (p) => {
          const signed = p.direction === 'left' ? p.degrees : -p.degrees;
          const report = await this.#await(this.robot.rotateDeg(signed));
          return this.#motionData(report);
        }),
      moveForward: (distanceCm) =>
        b.call('moveForward', { distanceCm }, async (p) => straight(p.distanceCm)),
      moveBackward: (distanceCm) =>
        b.call('moveBackward', { distanceCm }, async (p) => straight(-p.distanceCm)),
      stop: () =>
        b.call('stop', {}, async () => {
          const stopped = this.robot.stop();
          return { stopped, pose: this.#poseData() };
        }),
      getPose: async (): Promise<Pose> => {
        const r = this.robot;
        const v = r.velocity();
        return {
          position: { x: r.x, y: r.y, z: 0 },
          rotation: { yaw: r.yaw, pitch: 0, roll: 0 },
          velocity: { linear: v.linear, angular: v.angular },
        };
      },
    };
  }

  #makeVision(): VisionInterface {
    const lacks = (what: string, capability: string) =>
      new HalError('NOT_IMPLEMENTED', `the simulated robot has no ${what}`, {
        details: { capability },
      });
    const requireReady = (call: string) => {
      if (!this.#ready) {
        throw new HalError(
          'NOT_READY',
          `${call}: the HAL is not initialised; call initialize() first`,
        );
      }
    };
    return {
      captureFrame: async () => {
        requireReady('captureFrame');
        if (!this.#features.camera) throw lacks('camera', CAPABILITIES.camera);
        return this.#frameSource(this.world, this.robot);
      },
      scan: async (mode = 'quick') => {
        requireReady('scan');
        if (!this.#features.rangeSensors) throw lacks('range sensors', CAPABILITIES.rangeSensors);
        return scanAround(this.world, this.robot, mode, this.#options.rangeSensors);
      },
      getDistanceSensors: async () => {
        requireReady('getDistanceSensors');
        if (!this.#features.rangeSensors) throw lacks('range sensors', CAPABILITIES.rangeSensors);
        return readDistanceSensors(this.world, this.robot, this.#options.rangeSensors);
      },
      getLineSensors: async () => {
        throw lacks('line sensors', CAPABILITIES.lineSensors);
      },
      getIMU: async () => {
        requireReady('getIMU');
        if (this.#features.imu) return readImu(this.robot);
        return {
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: this.robot.velocity().angular },
          heading: this.robot.yaw,
          source: 'odometry',
        };
      },
    };
  }

  #makeCommunication(): CommunicationInterface {
    const b = this.#boundary;
    return {
      speak: (text, urgency) =>
        b.call('speak', { text, urgency }, async (p) => {
          if (!this.#features.speaker) {
            throw new HalError('NOT_IMPLEMENTED', 'the simulated robot has no speaker', {
              details: { capability: CAPABILITIES.speaker },
            });
          }
          this.events.emit('communication', {
            type: 'speak',
            text: p.text,
            urgency: p.urgency ?? 'info',
          });
          return { spoken: p.text };
        }),
      playSound: (soundId) =>
        b.call('playSound', { soundId }, async (p) => {
          if (!this.#features.speaker) {
            throw new HalError('NOT_IMPLEMENTED', 'the simulated robot has no speaker', {
              details: { capability: CAPABILITIES.sound },
            });
          }
          this.events.emit('communication', { type: 'sound', soundId: p.soundId });
          return { soundId: p.soundId };
        }),
      setLED: (r, g, bl, pattern) =>
        b.call('setLED', { r, g, b: bl, pattern }, async (p) => {
          const led = { r: p.r, g: p.g, b: p.b, pattern: p.pattern ?? 'solid' } as const;
          this.robot.setLed(led);
          this.events.emit('communication', { type: 'led', ...led });
          return { led };
        }),
      log: (message, level = 'info') => {
        try {
          const text = String(message);
          this.#logs.push(text);
          if (this.#logs.length > 1000) this.#logs.shift();
          this.#logger[level]?.(text);
          this.events.emit('communication', {
            type: 'log',
            message: text,
            level,
            atMs: this.world.nowUs / 1000,
          });
        } catch {
          // log() never throws.
        }
      },
    };
  }

  #makeSafety(): SafetyInterface {
    const b = this.#boundary;
    const status = (): SafetyStatus => {
      const r = this.robot;
      const errors: string[] = [];
      if (r.lastTrip !== undefined) {
        errors.push(`${r.lastTrip.reason}: ${r.lastTrip.detail}`);
      }
      const s: SafetyStatus = {
        emergencyStopped: r.emergencyStopped,
        batteryLevel: 100,
        errors,
      };
      if (r.emergencyStopped) s.emergencyStopReason = r.emergencyStopReason;
      return s;
    };
    return {
      emergencyStop: (reason) =>
        b.call('emergencyStop', { reason }, async (p) => {
          this.robot.emergencyStop(p.reason ?? 'estop command');
          this.events.emit('safety', status());
          return { estop: true, reason: this.robot.emergencyStopReason };
        }),
      isEmergencyStopped: () => this.robot.emergencyStopped,
      resetEmergencyStop: () =>
        b.call('resetEmergencyStop', {}, async () => {
          const was = this.robot.resetEmergencyStop();
          this.events.emit('safety', status());
          return { estop: false, wasEstopped: was };
        }),
      getSafetyStatus: status,
    };
  }
}
