// A minimal, ideal HAL: motions complete instantly and exactly. It proves the contract suite, and
// tests that need a HAL on the other end of a wire or a wrapper use it (from @hal/types/testing);
// real HALs live in @hal/simulation and @hal/physical.
import { CAPABILITIES } from '../capabilities.js';
import { HalError } from '../errors.js';
import type {
  CommunicationInterface,
  HardwareAbstractionLayer,
  LocomotionInterface,
  SafetyInterface,
  VisionInterface,
} from '../interfaces.js';
import type { DeviceInfo, Pose, SafetyStatus } from '../pose.js';
import { maxLinearSpeedMPerS, V1_ROBOT } from '../robot-config.js';
import { HalBoundary } from '../validation.js';
import { normalizeAngle } from '../vocabulary/angle.js';

export class ReferenceHAL implements HardwareAbstractionLayer {
  readonly mode = 'simulation' as const;
  readonly locomotion: LocomotionInterface;
  readonly vision: VisionInterface;
  readonly communication: CommunicationInterface;
  readonly safety: SafetyInterface;
  /** Every message passed to communication.log, for tests. */
  readonly logged: string[] = [];
  /** Why each refused communication.log call was refused, for tests. */
  readonly refusedLogs: string[] = [];

  #ready = false;
  #estop = false;
  #estopReason: string | undefined;
  #x = 0;
  #y = 0;
  #yaw = 0;
  readonly #boundary = new HalBoundary({
    mode: this.mode,
    config: () => V1_ROBOT,
    isEmergencyStopped: () => this.#estop,
    isReady: () => this.#ready,
  });

  constructor() {
    const b = this.#boundary;
    const forward = (cm: number) => {
      this.#x += (cm / 100) * Math.cos(this.#yaw);
      this.#y += (cm / 100) * Math.sin(this.#yaw);
    };
    this.locomotion = {
      drive: (left, right, durationMs) =>
        b.call('drive', { left, right, durationMs }, async (p) => {
          const seconds = (p.durationMs ?? 0) / 1000;
          const v = (maxLinearSpeedMPerS(V1_ROBOT) * 100) / 255;
          const dl = p.left * v * seconds;
          const dr = p.right * v * seconds;
          this.#yaw = normalizeAngle(this.#yaw + (dr - dl) / V1_ROBOT.wheelBaseCm);
          forward((dl + dr) / 2);
          return { leftSps: p.left, rightSps: p.right, running: false };
        }),
      moveTo: (x, y, z, speed) =>
        b.call('moveTo', { x, y, z, speed }, async (p) => {
          this.#yaw = Math.atan2(p.y - this.#y, p.x - this.#x);
          this.#x = p.x;
          this.#y = p.y;
        }),
      rotate: (direction, degrees) =>
        b.call('rotate', { direction, degrees }, async (p) => {
          const sign = p.direction === 'left' ? 1 : -1;
          this.#yaw = normalizeAngle(this.#yaw + (sign * p.degrees * Math.PI) / 180);
        }),
      moveForward: (distanceCm) =>
        b.call('moveForward', { distanceCm }, async (p) => forward(p.distanceCm)),
      moveBackward: (distanceCm) =>
        b.call('moveBackward', { distanceCm }, async (p) => forward(-p.distanceCm)),
      stop: () =>
        b.call('stop', {}, async () => ({
          stopped: false,
          pose: { x: this.#x, y: this.#y, yaw: this.#yaw },
        })),
      getPose: () =>
        b.read('getPose', {}, (): Pose => ({
          position: { x: this.#x, y: this.#y, z: 0 },
          rotation: { yaw: this.#yaw, pitch: 0, roll: 0 },
          velocity: { linear: 0, angular: 0 },
        })),
    };
    const lacks = (what: string): never => {
      throw new HalError('NOT_IMPLEMENTED', `the reference robot has no ${what}`);
    };
    this.vision = {
      captureFrame: () => b.read('captureFrame', {}, () => lacks('camera')),
      scan: (mode) => b.read('scan', { mode }, () => lacks('range sensors')),
      getDistanceSensors: () => b.read('getDistanceSensors', {}, () => lacks('range sensors')),
      getLineSensors: () => b.read('getLineSensors', {}, () => lacks('line sensors')),
      getIMU: () =>
        b.read('getIMU', {}, () => ({
          acceleration: { x: 0, y: 0, z: 0 },
          gyroscope: { x: 0, y: 0, z: 0 },
          heading: this.#yaw,
          source: 'odometry' as const,
        })),
    };
    this.communication = {
      speak: (text, urgency) => b.call('speak', { text, urgency }, async () => lacks('speaker')),
      playSound: (soundId) => b.call('playSound', { soundId }, async () => lacks('speaker')),
      setLED: (r, g, bl, pattern) =>
        b.call('setLED', { r, g, b: bl, pattern }, async (p) => ({
          led: { r: p.r, g: p.g, b: p.b, pattern: p.pattern ?? 'solid' },
        })),
      log: (message, level) => {
        const result = b.notify('log', { message, level }, (p) => {
          this.logged.push(p.message);
        });
        if (!result.success) this.refusedLogs.push(result.error ?? '');
      },
    };
    this.safety = {
      emergencyStop: (reason) =>
        b.call('emergencyStop', { reason }, async (p) => {
          this.#estop = true;
          this.#estopReason = p.reason;
          return { estop: true, reason: p.reason };
        }),
      isEmergencyStopped: () => this.#estop,
      resetEmergencyStop: () =>
        b.call('resetEmergencyStop', {}, async () => {
          const was = this.#estop;
          this.#estop = false;
          this.#estopReason = undefined;
          return { estop: false, wasEmergencyStopped: was };
        }),
      getSafetyStatus: (): SafetyStatus => ({
        emergencyStopped: this.#estop,
        batteryLevel: 100,
        errors: [],
        ...(this.#estopReason === undefined ? {} : { emergencyStopReason: this.#estopReason }),
      }),
    };
  }

  async initialize(): Promise<void> {
    this.#ready = true;
  }

  async cleanup(): Promise<void> {
    this.#ready = false;
  }

  isReady(): boolean {
    return this.#ready;
  }

  getDeviceInfo(): DeviceInfo {
    return {
      id: 'reference-1',
      type: 'reference',
      mode: this.mode,
      capabilities: [CAPABILITIES.differentialDrive, CAPABILITIES.led, CAPABILITIES.emergencyStop],
    };
  }
}
