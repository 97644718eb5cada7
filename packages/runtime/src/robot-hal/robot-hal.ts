import { HalBoundary } from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALMode,
  HardwareAbstractionLayer,
  LocomotionInterface,
  RobotConfig,
  RobotPort,
  SafetyInterface,
  VisionInterface,
} from '@hal/types';
import { createCommunication } from './communication.js';
import { createLocomotion } from './locomotion.js';
import { createSafety } from './safety.js';
import { createVision } from './vision.js';

/**
 * The HAL of a differential-drive robot, over the {@link RobotPort} of its world: every call goes
 * through the shared {@link HalBoundary} (readiness, the e-stop gate, validation against the
 * robot's own limits, timing, results), then becomes the firmware command it stands for, which
 * the port executes. `SimulationHAL` is this class over the simulated world's robot,
 * `PhysicalHAL` over the cube's wire session (UDP or serial); what only one world has is on its
 * binding, `hal.binding`.
 */
export class RobotHAL<Port extends RobotPort = RobotPort> implements HardwareAbstractionLayer {
  readonly mode: HALMode;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  /** The robot this HAL drives, as its world provides it. */
  readonly binding: Port;
  /** The boundary every call goes through (its call schemas follow the robot's configuration). */
  protected readonly boundary: HalBoundary;

  #initialized = false;
  #opening: Promise<void> | undefined;
  readonly #logs: string[] = [];

  constructor(binding: Port) {
    this.binding = binding;
    this.mode = binding.mode;
    this.boundary = new HalBoundary({
      mode: binding.mode,
      config: () => binding.config(),
      isEmergencyStopped: () => binding.isEmergencyStopped(),
      // initialised is enough here: a lost link is reported by the call itself, as NOT_CONNECTED
      isReady: () => this.#initialized,
      now: () => binding.now(),
    });
    // the call schemas for the robot now, not on the first call after it changed
    binding.onConfigChanged?.(() => this.boundary.schemas());
    this.locomotion = createLocomotion(this.boundary, binding);
    this.vision = createVision(this.boundary, binding);
    this.communication = createCommunication(this.boundary, binding, this.#logs);
    this.safety = createSafety(this.boundary, binding);
  }

  /** Opens the robot (once, however many callers wait for it). */
  async initialize(): Promise<void> {
    if (this.#initialized) return;
    this.#opening ??= this.binding
      .open()
      .then(() => {
        this.#initialized = true;
      })
      .finally(() => {
        this.#opening = undefined;
      });
    return this.#opening;
  }

  /** Stops the motors and lets the robot go. Safe to call twice. */
  async cleanup(): Promise<void> {
    await this.#opening?.catch(() => undefined);
    this.#initialized = false;
    await this.binding.close();
  }

  /** Between `initialize()` and `cleanup()`, while the robot can be reached. */
  isReady(): boolean {
    return this.#initialized && this.binding.isConnected();
  }

  getDeviceInfo(): DeviceInfo {
    return this.binding.deviceInfo();
  }

  /** The geometry and limits every call is validated against (as the robot reports them). */
  get robotConfig(): RobotConfig {
    return this.binding.config();
  }

  /** Messages passed to `communication.log`, oldest first (the last 1000). */
  get logs(): readonly string[] {
    return this.#logs;
  }
}
