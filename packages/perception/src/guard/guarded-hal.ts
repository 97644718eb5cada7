import { isHalError, scoped, silentLogger, V1_ROBOT } from '@hal/types';
import type {
  CommunicationInterface,
  DeviceInfo,
  HALMode,
  HALToolResult,
  HardwareAbstractionLayer,
  ManipulationInterface,
  RobotConfig,
  SafetyInterface,
  ScopedLogger,
  VisionInterface,
} from '@hal/types';
import type { Detector } from '../detector.js';
import { FramePerceiver } from '../frame-perceiver.js';
import { CameraSight } from './camera-sight.js';
import { guardSettings } from './guard-settings.js';
import type { GuardOptions, GuardSettings } from './guard-settings.js';
import { GuardRecord } from './guard-status.js';
import type { GuardListener, GuardStatus } from './guard-status.js';
import { GuardedLocomotion } from './guarded-locomotion.js';
import { RangeSight } from './range-sight.js';
import type { GuardSource, Sight } from './sighting.js';

/** The guard needs free space only: no objects are looked for. */
const NO_OBJECTS: Detector = Object.freeze({ name: 'none', detect: () => [] });

const notImplemented = (error: unknown) => isHalError(error) && error.code === 'NOT_IMPLEMENTED';

/**
 * A HAL that forwards every call to `hal` and stops the robot before an obstacle ahead: the
 * guard, a safety layer between the leash and the robot (docs/tools.md, "The guard").
 * - A forward motion (moveForward, moveTo, drive with positive power) is looked ahead of before
 *   it starts (refused OBSTACLE_AHEAD, nothing moved, when something is within the stand-off) and
 *   driven in legs no longer than the free distance seen less the stand-off (and a margin for the
 *   sense's error), looking again before each; while a leg runs a watcher looks at the camera's
 *   rate and stops the robot when something comes within the stand-off, or when it has seen
 *   nothing for `blindLimitMs` (TIMEOUT: it stops rather than drive blind).
 * - It sees with the range sensors where the robot has them, else the camera's free space.
 * - A reverse passes unwatched (said once) or is refused (`reverse: 'refuse'`); a turn in place
 *   passes; `stop`, the e-stop and every read go straight through, never waiting on the guard.
 * - With no camera and no range sensors it says once that it cannot guard (a warning, and
 *   `status().warning`) and lets motions through.
 */
export class GuardedHAL implements HardwareAbstractionLayer {
  readonly locomotion: GuardedLocomotion;
  readonly safety: SafetyInterface;
  readonly manipulation?: ManipulationInterface;
  readonly settings: GuardSettings;
  readonly #hal: HardwareAbstractionLayer;
  readonly #record: GuardRecord;
  readonly #log: ScopedLogger;
  readonly #options: GuardOptions;
  #sight: Sight | undefined;
  #known = false;
  #probing: Promise<Sight | undefined> | undefined;

  constructor(hal: HardwareAbstractionLayer, options: GuardOptions = {}) {
    this.#hal = hal;
    this.#options = options;
    this.settings = guardSettings(options);
    this.#record = new GuardRecord(this.settings.standoffM);
    this.#log = scoped(options.logger ?? silentLogger, 'hal:guard');
    this.locomotion = new GuardedLocomotion({
      hal,
      settings: this.settings,
      record: this.#record,
      log: this.#log,
      sight: () => this.#senses(),
    });
    if (hal.manipulation !== undefined) this.manipulation = hal.manipulation;
    const locomotion = this.locomotion;
    this.safety = {
      emergencyStop: (reason?: string): Promise<HALToolResult> => {
        const stopping = hal.safety.emergencyStop(reason);
        locomotion.cancel();
        return stopping;
      },
      isEmergencyStopped: () => hal.safety.isEmergencyStopped(),
      resetEmergencyStop: () => hal.safety.resetEmergencyStop(),
      getSafetyStatus: () => hal.safety.getSafetyStatus(),
    };
  }

  /** The HAL guarded. */
  get inner(): HardwareAbstractionLayer {
    return this.#hal;
  }

  get mode(): HALMode {
    return this.#hal.mode;
  }

  get vision(): VisionInterface {
    return this.#hal.vision;
  }

  get communication(): CommunicationInterface {
    return this.#hal.communication;
  }

  /** The guarded HAL's configuration (the V1 robot's where it has none, as tools read it). */
  get robotConfig(): RobotConfig {
    return this.#hal.robotConfig ?? V1_ROBOT;
  }

  initialize(): Promise<void> {
    return this.#hal.initialize();
  }

  cleanup(): Promise<void> {
    this.locomotion.cancel();
    return this.#hal.cleanup();
  }

  isReady(): boolean {
    return this.#hal.isReady();
  }

  getDeviceInfo(): DeviceInfo {
    return this.#hal.getDeviceInfo();
  }

  /** What the guard has done: stops, refusals, whether it can see, the last stop. */
  status(): GuardStatus {
    return this.#record.status();
  }

  /** Calls `listener` with each stop, blind stop, unwatched motion; returns its removal. */
  onEvent(listener: GuardListener): () => void {
    return this.#record.on(listener);
  }

  /**
   * What the guard sees with, finding out now if it has not yet (it looks once with each sense);
   * 'nothing' when the robot has neither a camera nor range sensors; 'unknown' while the HAL is
   * not ready.
   */
  async senses(): Promise<GuardSource | 'nothing' | 'unknown'> {
    const sight = await this.#senses();
    return sight?.source ?? (this.#known ? 'nothing' : 'unknown');
  }

  #senses(): Promise<Sight | undefined> {
    if (this.#known) return Promise.resolve(this.#sight);
    this.#probing ??= this.#probe().finally(() => {
      this.#probing = undefined;
    });
    return this.#probing;
  }

  async #probe(): Promise<Sight | undefined> {
    // a HAL that is not ready says nothing of its senses: ask again when it is
    if (!this.#hal.isReady()) return undefined;
    const { sense, bodyRadiusM, corridorMarginM, lookTimeoutMs } = this.settings;
    const geometry = {
      bodyRadiusM,
      halfWidthM: bodyRadiusM + corridorMarginM,
      timeoutMs: lookTimeoutMs,
    };
    if (sense !== 'camera') {
      const range = new RangeSight(this.#hal, geometry);
      try {
        await range.look();
        return this.#settle(range);
      } catch (error) {
        // range sensors that answer badly are still there: each motion needs a good look
        if (sense === 'range' && !notImplemented(error)) return this.#settle(range);
      }
    }
    if (sense !== 'range') {
      const camera = new CameraSight(this.#hal, () => this.#perceiver(), geometry);
      try {
        await camera.look();
        return this.#settle(camera);
      } catch (error) {
        if (!notImplemented(error)) return this.#settle(camera);
      }
    }
    const lacks =
      sense === 'auto'
        ? 'no camera and no range sensors'
        : sense === 'camera'
          ? 'no camera'
          : 'no range sensors';
    const message = `the guard cannot see: the robot has ${lacks}; motions pass unwatched`;
    this.#log.warn(message);
    this.#record.cannotGuard(message);
    return this.#settle(undefined);
  }

  #settle(sight: Sight | undefined): Sight | undefined {
    this.#sight = sight;
    this.#known = true;
    this.#record.sees = sight?.source ?? 'nothing';
    return sight;
  }

  #perceiver(): FramePerceiver {
    if (this.#options.perceiver !== undefined) return this.#options.perceiver();
    // the camera the robot reports (its configuration or calibration) unless one is given
    const camera = this.#options.camera ?? this.#hal.getDeviceInfo().camera;
    return new FramePerceiver({
      ...(camera === undefined ? {} : { camera }),
      detector: NO_OBJECTS,
    });
  }
}

/** Guards `hal` (see {@link GuardedHAL}). */
export function guardHal(hal: HardwareAbstractionLayer, options: GuardOptions = {}): GuardedHAL {
  return new GuardedHAL(hal, options);
}
