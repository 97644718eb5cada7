import { CAPABILITIES, HalBoundary, robotConfig, silentLogger, V1_ROBOT } from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALConfig,
  HardwareAbstractionLayer,
  LocomotionInterface,
  RobotConfig,
  SafetyInterface,
  TypedEmitter,
  VisionInterface,
} from '@hal/types';
import { cameraModelOf } from '../camera.js';
import type { SimRobot } from '../robot/sim-robot.js';
import { listenerSafeEmitter, World } from '../world.js';
import { createCommunication } from './communication.js';
import type { HalContext } from './context.js';
import type { SimulationHALEvents } from './events.js';
import { optionsFromConfig } from './from-config.js';
import { createLocomotion } from './locomotion.js';
import { resolveFeatures } from './options.js';
import type { SimulatedFeatures, SimulationClock, SimulationHALOptions } from './options.js';
import { createSafety } from './safety.js';
import { createVision, softwareFrameSource } from './vision.js';

/**
 * The HAL of a simulated robot. Each call is mapped to the firmware command a PhysicalHAL sends
 * (see docs/simulation.md) and executed by a {@link SimRobot} that moves as the firmware does.
 * The subsystems are built in their own modules over one shared {@link HalContext}.
 */
export class SimulationHAL implements HardwareAbstractionLayer {
  readonly mode = 'simulation' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  readonly world: World;
  readonly events: TypedEmitter<SimulationHALEvents>;

  readonly #robotId: string;
  readonly #clock: SimulationClock;
  readonly #options: SimulationHALOptions;
  readonly #features: Required<SimulatedFeatures>;
  #ready = false;
  #startedTicker = false;
  readonly #logs: string[] = [];

  constructor(options: SimulationHALOptions = {}) {
    this.#options = options;
    this.events = listenerSafeEmitter(options.logger, 'hal:simulation');
    this.world =
      options.world ?? new World(options.logger === undefined ? {} : { logger: options.logger });
    this.#clock = options.clock ?? 'fast';
    this.#features = resolveFeatures(options.features);
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
    this.world.nameDevice(this.#robotId, this.getDeviceInfo().id);
    const boundary = new HalBoundary({
      mode: this.mode,
      config: () => this.robot.config,
      isEmergencyStopped: () => this.robot.emergencyStopped,
      isReady: () => this.#ready,
      now: () => this.world.nowUs / 1000,
    });
    const context: HalContext = {
      world: this.world,
      robot: () => this.robot,
      boundary,
      events: this.events,
      clock: this.#clock,
      features: this.#features,
      options,
    };
    this.locomotion = createLocomotion(context);
    this.vision = createVision(
      context,
      options.frameSource ?? softwareFrameSource(options.camera ?? {}, options.jpegEncoder),
    );
    this.communication = createCommunication(context, this.#logs, options.logger ?? silentLogger);
    this.safety = createSafety(context);
  }

  /**
   * Builds a SimulationHAL from the shared {@link HALConfig} (the way PhysicalHAL is built):
   * `mode` must be 'simulation'; `simulator` may be the {@link World} to join (default a new
   * one); `robot` overrides the V1 geometry and limits; `deviceId` names the device; and
   * `capabilities`, when given, chooses the simulated features (camera, range sensors, IMU,
   * speaker) by their capability strings. Throws INVALID_PARAMETER on a bad configuration.
   */
  static fromConfig(config: HALConfig, options: SimulationHALOptions = {}): SimulationHAL {
    return new SimulationHAL(optionsFromConfig(config, options));
  }

  /** The simulated robot this HAL drives (looked up by id: a map change re-creates it). */
  get robot(): SimRobot {
    return this.world.robot(this.#robotId);
  }

  /** The geometry and limits of the simulated robot, which every call is validated against. */
  get robotConfig(): RobotConfig {
    return this.robot.config;
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
      // the model the camera renders with, so perception projects with the same one
      ...(this.#features.camera ? { camera: cameraModelOf(this.#options.camera) } : {}),
    };
  }

  /**
   * Simulates the host going silent (no heartbeats between commands): a running motion stops
   * after the robot's host timeout, as the firmware's does. `false` makes the host talk again.
   */
  simulateHostSilence(silent: boolean): void {
    this.robot.setHostSilent(silent);
  }
}
