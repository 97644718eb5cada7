import { HalError, stepsPerCm, V1_ROBOT } from '@hal/types';
import type {
  DeviceInfo,
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
  SafetyStatus,
} from '@hal/types';

/**
 * An in-process robot port for unit tests of the HAL class: motions happen at once and move the
 * pose exactly (no steps, no clock); it records every command it was given.
 */
export class FakePort implements RobotPort {
  readonly mode = 'simulation' as const;
  readonly commands: Array<
    | MotionCommand
    | { kind: 'drive'; leftSps: number; rightSps: number; durationMs?: number | undefined }
    | { kind: 'stop' }
  > = [];
  readonly logged: Array<[string, HALLogLevel]> = [];
  readonly refusals: Array<{ code?: string | undefined; error?: string | undefined }> = [];
  opens = 0;
  closes = 0;
  imu?: () => IMUReading;
  checkTarget?: (x: number, y: number) => void;
  readonly #config: RobotConfig;
  #x = 0;
  #y = 0;
  #yaw = 0;
  #open = false;
  #estop: string | undefined;
  #moveId = 0;

  constructor(config: RobotConfig = V1_ROBOT) {
    this.#config = config;
  }

  async open(): Promise<void> {
    this.opens += 1;
    await Promise.resolve();
    this.#open = true;
  }
  async close(): Promise<void> {
    this.closes += 1;
    this.#open = false;
  }
  isConnected(): boolean {
    return this.#open;
  }
  now(): number {
    return 0;
  }
  config(): RobotConfig {
    return this.#config;
  }
  deviceInfo(): DeviceInfo {
    return { id: 'fake', type: 'fake', mode: this.mode, capabilities: [] };
  }
  pose(): Pose {
    return {
      position: { x: this.#x, y: this.#y, z: 0 },
      rotation: { yaw: this.#yaw, pitch: 0, roll: 0 },
      velocity: { linear: 0, angular: 0.25 },
      confirmed: true,
    };
  }
  async motion(command: MotionCommand): Promise<MotionDone> {
    this.commands.push(command);
    this.#moveId += 1;
    const perCm = stepsPerCm(this.#config);
    if (command.kind === 'rotate') {
      this.#yaw += (command.degrees * Math.PI) / 180;
      const steps = Math.round(
        (command.degrees / 360) * Math.PI * this.#config.wheelBaseCm * perCm,
      );
      return { moveId: this.#moveId, leftSteps: -steps, rightSteps: steps, plannedDurationMs: 1 };
    }
    const m = command.leftCm / 100;
    this.#x += m * Math.cos(this.#yaw);
    this.#y += m * Math.sin(this.#yaw);
    const steps = Math.round(command.leftCm * perCm);
    return { moveId: this.#moveId, leftSteps: steps, rightSteps: steps, plannedDurationMs: 1 };
  }
  async drive(leftSps: number, rightSps: number, durationMs?: number): Promise<DriveDone> {
    this.commands.push({ kind: 'drive', leftSps, rightSps, durationMs });
    this.#moveId += 1;
    return {
      moveId: this.#moveId,
      leftSps,
      rightSps,
      speedClamped: false,
      running: durationMs === undefined,
    };
  }
  async stop(): Promise<boolean> {
    this.commands.push({ kind: 'stop' });
    return false;
  }
  async emergencyStop(reason: string): Promise<EmergencyStopDone> {
    this.#estop = reason;
    return { estop: true, reason, delivered: this.#open };
  }
  async resetEmergencyStop(): Promise<boolean> {
    const was = this.#estop !== undefined;
    this.#estop = undefined;
    return was;
  }
  isEmergencyStopped(): boolean {
    return this.#estop !== undefined;
  }
  safetyStatus(): SafetyStatus {
    return { emergencyStopped: this.isEmergencyStopped(), batteryLevel: 100, errors: [] };
  }
  async setLed(led: LedSetting): Promise<LitLed> {
    return { ...led };
  }
  log(message: string, level: HALLogLevel): void {
    this.logged.push([message, level]);
  }
  logRefused(refusal: { code?: string | undefined; error?: string | undefined }): void {
    this.refusals.push(refusal);
  }
  lacks(part: RobotPart): HalError {
    return new HalError('NOT_IMPLEMENTED', `the fake robot has no ${part}`);
  }
}
