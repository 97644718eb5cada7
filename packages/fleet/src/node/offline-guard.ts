import { V1_ROBOT, deviceOfflineError, failureResult } from '@hal/types';
import type { HalError } from '@hal/types';
import type {
  CommunicationInterface,
  HALToolResult,
  HardwareAbstractionLayer,
  LocomotionInterface,
  RobotConfig,
  SafetyInterface,
  VisionInterface,
} from '@hal/types';

/** The error of a call to a device the manager sees offline. */
export function offlineError(device: string): HalError {
  return deviceOfflineError(device);
}

/**
 * The HAL the device manager hands out: the device's own HAL, except that while the device is
 * offline every call fails at once with NOT_CONNECTED (details `{ device, offline: true }`)
 * instead of waiting for a robot that is not there. The e-stop always goes through (a HAL latches
 * it on the host whatever the link does), and so do the cached safety reads and `log`.
 */
export class OfflineGuardHAL implements HardwareAbstractionLayer {
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  readonly #inner: HardwareAbstractionLayer;
  readonly #device: string;
  readonly #offline: () => boolean;

  constructor(inner: HardwareAbstractionLayer, device: string, offline: () => boolean) {
    this.#inner = inner;
    this.#device = device;
    this.#offline = offline;
    const l = inner.locomotion;
    const v = inner.vision;
    const c = inner.communication;
    const s = inner.safety;
    this.locomotion = {
      drive: (left, right, ms) => this.#result(() => l.drive(left, right, ms)),
      moveTo: (x, y, z, speed) => this.#result(() => l.moveTo(x, y, z, speed)),
      rotate: (direction, degrees) => this.#result(() => l.rotate(direction, degrees)),
      moveForward: (cm) => this.#result(() => l.moveForward(cm)),
      moveBackward: (cm) => this.#result(() => l.moveBackward(cm)),
      stop: () => this.#result(() => l.stop()),
      getPose: () => this.#value(() => l.getPose()),
    };
    this.vision = {
      captureFrame: () => this.#value(() => v.captureFrame()),
      scan: (mode) => this.#value(() => v.scan(mode)),
      getDistanceSensors: () => this.#value(() => v.getDistanceSensors()),
      getLineSensors: () => this.#value(() => v.getLineSensors()),
      getIMU: () => this.#value(() => v.getIMU()),
    };
    this.communication = {
      speak: (text, urgency) => this.#result(() => c.speak(text, urgency)),
      setLED: (r, g, b, pattern) => this.#result(() => c.setLED(r, g, b, pattern)),
      playSound: (id) => this.#result(() => c.playSound(id)),
      log: (message, level) => c.log(message, level),
    };
    this.safety = {
      emergencyStop: (reason) => s.emergencyStop(reason),
      resetEmergencyStop: () => this.#result(() => s.resetEmergencyStop()),
      isEmergencyStopped: () => s.isEmergencyStopped(),
      getSafetyStatus: () => s.getSafetyStatus(),
    };
  }

  get mode(): HardwareAbstractionLayer['mode'] {
    return this.#inner.mode;
  }

  /** The device's geometry and limits (the V1 robot when its HAL does not say). */
  get robotConfig(): RobotConfig {
    return this.#inner.robotConfig ?? V1_ROBOT;
  }

  /** The HAL this guards. */
  get inner(): HardwareAbstractionLayer {
    return this.#inner;
  }

  initialize(): Promise<void> {
    return this.#inner.initialize();
  }

  cleanup(): Promise<void> {
    return this.#inner.cleanup();
  }

  isReady(): boolean {
    return !this.#offline() && this.#inner.isReady();
  }

  getDeviceInfo(): ReturnType<HardwareAbstractionLayer['getDeviceInfo']> {
    return this.#inner.getDeviceInfo();
  }

  #result(call: () => Promise<HALToolResult>): Promise<HALToolResult> {
    if (this.#offline()) {
      return Promise.resolve(failureResult(this.mode, Date.now(), offlineError(this.#device), 0));
    }
    return call();
  }

  #value<T>(call: () => Promise<T>): Promise<T> {
    if (this.#offline()) return Promise.reject(offlineError(this.#device));
    return call();
  }
}
