import {
  CAPABILITIES,
  ROBOT_PART_CAPABILITY,
  HalError,
  lastTripError,
  scoped,
  silentLogger,
  V1_ROBOT,
  robotConfig,
} from '@hal/types';
import type {
  DeviceInfo,
  DistanceSensors,
  DriveDone,
  EmergencyStopDone,
  HALLogLevel,
  IMUReading,
  LedSetting,
  LitLed,
  MotionCommand,
  MotionDone,
  Pose,
  RobotConfig,
  RobotPart,
  RobotPort,
  RobotSpeaker,
  SafetyStatus,
  ScanResult,
  ScopedLogger,
  TypedEmitter,
} from '@hal/types';
import { cameraModelOf } from '../camera.js';
import { SimulatedImu } from '../gyro.js';
import type { MotionHandle, MotionReport } from '../robot/motion-report.js';
import type { SimRobot } from '../robot/sim-robot.js';
import { readDistanceSensors, scanAround } from '../sensors.js';
import { listenerSafeEmitter, World } from '../world.js';
import { checkInsideArena } from './arena-bounds.js';
import { awaitMotion } from './await-motion.js';
import type { HalContext } from './context.js';
import type { SimulationHALEvents } from './events.js';
import { resolveFeatures, SIMULATION_HAL_DEFAULTS } from './options.js';
import type { SimulatedFeatures, SimulationClock, SimulationHALOptions } from './options.js';
import { softwareFrameSource } from './frame-source.js';

/**
 * The simulated world's robot as a {@link RobotPort}: each command is the firmware command a
 * PhysicalHAL sends (docs/simulation.md), executed by a {@link SimRobot} that moves as the firmware
 * does and waited for on the world's clock. Its sensors are the world's (the camera renders it,
 * range sensors cast rays in it, the IMU drifts as a MEMS one does), each only when the robot has
 * the feature. What only the simulation has (the world, its events, host silence) is here too.
 */
export class WorldBinding implements RobotPort {
  readonly mode = 'simulation' as const;
  readonly world: World;
  readonly events: TypedEmitter<SimulationHALEvents>;
  readonly features: Required<SimulatedFeatures>;
  readonly captureFrame?: () => Promise<string>;
  readonly scan?: (mode: 'full' | 'targeted' | 'quick') => Promise<ScanResult>;
  readonly distanceSensors?: () => Promise<DistanceSensors>;
  readonly imu?: () => IMUReading;
  readonly speaker?: RobotSpeaker;

  readonly #robotId: string;
  readonly #clock: SimulationClock;
  readonly #options: SimulationHALOptions;
  readonly #log: ScopedLogger;
  readonly #context: HalContext;
  #open = false;
  #startedTicker = false;

  constructor(options: SimulationHALOptions = {}) {
    this.#options = options;
    this.events = listenerSafeEmitter(options.logger, 'hal:simulation');
    this.#log = scoped(options.logger ?? silentLogger, 'hal:simulation');
    this.world =
      options.world ?? new World(options.logger === undefined ? {} : { logger: options.logger });
    this.#clock = options.clock ?? SIMULATION_HAL_DEFAULTS.clock;
    this.features = resolveFeatures(options.features);
    if (options.robotId !== undefined) {
      this.#robotId = this.world.robot(options.robotId).id;
    } else {
      const added = this.world.addRobot({
        config: options.robot === undefined ? V1_ROBOT : robotConfig(options.robot),
        ...(options.start === undefined ? {} : { start: options.start }),
        ...(options.bodyError === undefined ? {} : { bodyError: options.bodyError }),
      });
      this.#robotId = added.id;
    }
    this.world.nameDevice(this.#robotId, this.deviceInfo().id);
    this.#context = {
      world: this.world,
      robot: () => this.robot,
      events: this.events,
      clock: this.#clock,
      options,
    };
    if (this.features.camera) {
      const frames =
        options.frameSource ?? softwareFrameSource(options.camera ?? {}, options.jpegEncoder);
      this.captureFrame = () => frames(this.world, this.robot);
    }
    if (this.features.rangeSensors) {
      this.scan = async (mode) =>
        await scanAround(this.world, this.robot, mode, options.rangeSensors);
      this.distanceSensors = async () =>
        await readDistanceSensors(this.world, this.robot, options.rangeSensors);
    }
    if (this.features.imu) {
      // powered on with the HAL (or, for a robot a map change re-created, at its first read)
      const imuOf = this.#imus();
      imuOf(this.robot);
      this.imu = () => imuOf(this.robot).read(this.robot);
    }
    if (this.features.speaker) {
      this.speaker = {
        speak: async (text, urgency) => {
          this.events.emit('communication', { type: 'speak', text, urgency });
        },
        playSound: async (soundId) => {
          this.events.emit('communication', { type: 'sound', soundId });
        },
      };
    }
  }

  /** The simulated robot (looked up by id: a map change re-creates it). */
  get robot(): SimRobot {
    return this.world.robot(this.#robotId);
  }

  async open(): Promise<void> {
    if (this.#clock === 'realtime' && this.world.realtimeSpeed === 0) {
      this.world.startRealtime({
        speed: this.#options.realtimeSpeed ?? SIMULATION_HAL_DEFAULTS.realtimeSpeed,
      });
      this.#startedTicker = true;
    }
    // PhysicalHAL opens a session with `hello`, which resets the robot's distance accumulators.
    this.robot.hello();
    this.#open = true;
  }

  async close(): Promise<void> {
    if (!this.#open) return;
    this.#open = false;
    this.world.robots.find((r) => r.id === this.#robotId)?.stop();
    if (this.#startedTicker) this.world.stopRealtime();
    this.#startedTicker = false;
  }

  isConnected(): boolean {
    return this.#open;
  }

  now(): number {
    return this.world.nowUs / 1000;
  }

  config(): RobotConfig {
    return this.robot.config;
  }

  deviceInfo(): DeviceInfo {
    const caps: string[] = [
      CAPABILITIES.differentialDrive,
      `locomotion.stepper:v1.0:steps_per_rev=${this.robot.config.stepsPerRevolution}`,
      CAPABILITIES.led,
      CAPABILITIES.emergencyStop,
      'safety.host_timeout:v1.0',
    ];
    if (this.features.camera) caps.push(CAPABILITIES.camera);
    if (this.features.rangeSensors) caps.push(CAPABILITIES.rangeSensors);
    if (this.features.imu) caps.push(CAPABILITIES.imu);
    if (this.features.speaker) caps.push(CAPABILITIES.speaker, CAPABILITIES.sound);
    return {
      id: this.#options.deviceId ?? `sim-${this.#robotId}`,
      type: 'v1-stepper-cube',
      mode: this.mode,
      capabilities: caps,
      // the model the camera renders with, so perception projects with the same one
      ...(this.features.camera ? { camera: cameraModelOf(this.#options.camera) } : {}),
    };
  }

  /** The robot's odometry: what it counted, which it vouches for (`confirmed`). */
  pose(): Pose {
    const r = this.robot;
    const v = r.velocity();
    const p = r.reportedPose;
    return {
      position: { x: p.x, y: p.y, z: 0 },
      rotation: { yaw: p.yaw, pitch: 0, roll: 0 },
      velocity: { linear: v.linear, angular: v.angular },
      confirmed: true,
    };
  }

  checkTarget(x: number, y: number): void {
    checkInsideArena(this.world, this.robot, x, y);
  }

  async motion(command: MotionCommand): Promise<MotionDone> {
    const robot = this.robot;
    const handle: MotionHandle =
      command.kind === 'move'
        ? robot.moveCm(command.leftCm, command.rightCm, command.speedStepsPerS)
        : robot.rotateDeg(command.degrees, command.speedStepsPerS);
    return motionDone(await awaitMotion(this.#context, handle));
  }

  async drive(leftSps: number, rightSps: number, durationMs?: number): Promise<DriveDone> {
    const robot = this.robot;
    const handle = robot.drive(leftSps, rightSps, durationMs);
    if (handle === undefined) {
      // both speeds 0: the firmware stops, and reports the motion it stopped
      return {
        moveId: robot.motion?.moveId ?? 0,
        leftSps: 0,
        rightSps: 0,
        speedClamped: false,
        running: false,
      };
    }
    const started = {
      moveId: handle.report.moveId,
      leftSps: handle.report.leftSps,
      rightSps: handle.report.rightSps,
      speedClamped: handle.report.speedClamped,
    };
    if (durationMs === undefined) {
      this.events.emit('motionStarted', { ...handle.report });
      void handle.finished.then((r) => this.events.emit('motionFinished', { ...r }));
      return { ...started, running: true };
    }
    const report = await awaitMotion(this.#context, handle);
    return {
      ...started,
      running: false,
      leftSteps: report.doneLeft,
      rightSteps: report.doneRight,
    };
  }

  async stop(): Promise<boolean> {
    return this.robot.stop();
  }

  async emergencyStop(reason: string): Promise<EmergencyStopDone> {
    // before open() or after close() the simulated robot still latches
    const robot = this.robot;
    robot.emergencyStop(reason);
    this.events.emit('safety', this.safetyStatus());
    const motion = robot.motion;
    return {
      estop: true,
      reason: robot.emergencyStopReason,
      delivered: true,
      moveId: motion?.moveId ?? 0,
      moveOutcome: motion?.outcome ?? 'none',
      leftSteps: motion?.doneLeft ?? 0,
      rightSteps: motion?.doneRight ?? 0,
      robotEstopUs: robot.emergencyStopUs,
    };
  }

  async resetEmergencyStop(): Promise<boolean> {
    const was = this.robot.resetEmergencyStop();
    this.events.emit('safety', this.safetyStatus());
    return was;
  }

  isEmergencyStopped(): boolean {
    return this.robot.emergencyStopped;
  }

  safetyStatus(): SafetyStatus {
    const r = this.robot;
    const errors: string[] = [];
    if (r.lastTrip !== undefined) errors.push(lastTripError(r.lastTrip));
    const status: SafetyStatus = {
      emergencyStopped: r.emergencyStopped,
      batteryLevel: 100,
      errors,
    };
    if (r.emergencyStopped) status.emergencyStopReason = r.emergencyStopReason;
    return status;
  }

  async setLed(led: LedSetting): Promise<LitLed> {
    const set = { ...led } as const;
    this.robot.setLed(set);
    this.events.emit('communication', { type: 'led', ...set });
    return set;
  }

  log(message: string, level: HALLogLevel): void {
    this.#log[level](message);
    this.events.emit('communication', { type: 'log', message, level, atMs: this.now() });
  }

  logRefused(refusal: { code?: string | undefined; error?: string | undefined }): void {
    // scoped() swallows a broken logger's throw
    this.#log.warn(`log refused: ${refusal.error ?? refusal.code ?? 'unknown reason'}`);
  }

  lacks(part: RobotPart): HalError {
    return new HalError('NOT_IMPLEMENTED', `the simulated robot has no ${part}`, {
      details: { capability: ROBOT_PART_CAPABILITY[part] },
    });
  }

  /**
   * Simulates the host going silent (no heartbeats between commands): a running motion stops
   * after the robot's host timeout, as the firmware's does. `false` makes the host talk again.
   */
  simulateHostSilence(silent: boolean): void {
    this.robot.setHostSilent(silent);
  }

  /**
   * One IMU per robot (a map change re-creates the robot, and its IMU with it); its errors are
   * seeded from the world's random source when first read.
   */
  #imus(): (robot: SimRobot) => SimulatedImu {
    const imus = new WeakMap<SimRobot, SimulatedImu>();
    return (robot) => {
      let imu = imus.get(robot);
      if (imu === undefined) {
        imu = new SimulatedImu(robot, this.#options.imu ?? {}, () =>
          Math.floor(this.world.random.next() * 0x100000000),
        );
        imus.set(robot, imu);
      }
      return imu;
    };
  }
}

/** A finished move as a port reports it. */
function motionDone(report: MotionReport): MotionDone {
  return {
    moveId: report.moveId,
    leftSteps: report.doneLeft,
    rightSteps: report.doneRight,
    plannedDurationMs: Math.ceil(report.durationUs / 1000),
  };
}
