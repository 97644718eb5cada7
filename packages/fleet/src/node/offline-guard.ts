import {
  HAL_CALL_TABLE,
  V1_ROBOT,
  callMethod,
  deviceOfflineError,
  failureResult,
  forwardCalls,
  invokeSpec,
} from '@hal/types';
import type { CallSpec, CallTable, HalError } from '@hal/types';
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

  constructor(
    inner: HardwareAbstractionLayer,
    device: string,
    offline: () => boolean,
    calls: CallTable = HAL_CALL_TABLE,
  ) {
    this.#inner = inner;
    this.#device = device;
    this.#offline = offline;
    const forward = (spec: CallSpec, args: unknown[]): unknown => {
      // the cached safety reads and log answer at once, whatever the link does
      if (spec.cached || spec.kind === 'void') return callMethod(inner, spec, args);
      const run = () => invokeSpec(inner, spec, args);
      return spec.kind === 'value'
        ? this.#value(run)
        : this.#result(run as () => Promise<HALToolResult>);
    };
    const subsystems = forwardCalls(
      forward,
      { emergencyStop: (reason?: string) => inner.safety.emergencyStop(reason) },
      calls,
    );
    this.locomotion = subsystems.locomotion;
    this.vision = subsystems.vision;
    this.communication = subsystems.communication;
    this.safety = subsystems.safety;
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
