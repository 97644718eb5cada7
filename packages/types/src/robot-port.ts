import { CAPABILITIES } from './capabilities.js';
import type { HALLogLevel } from './interfaces.js';
import type { HALMode } from './mode.js';
import type {
  DeviceInfo,
  DistanceSensors,
  IMUReading,
  Pose,
  SafetyStatus,
  ScanResult,
} from './pose.js';
import type { RobotConfig } from './robot-config.js';

/** An LED setting: 0..255 per channel and a pattern. */
export interface LedSetting {
  r: number;
  g: number;
  b: number;
  pattern: 'solid' | 'blink' | 'pulse';
}

/** The LED as the robot reports it lit (the firmware also knows `off`). */
export interface LitLed {
  r: number;
  g: number;
  b: number;
  pattern: string;
}

/** A `move_cm` (left and right wheel distances) or a `rotate_deg` (in place, + counter-clockwise). */
export type MotionCommand =
  | { kind: 'move'; leftCm: number; rightCm: number; speedStepsPerS?: number | undefined }
  | { kind: 'rotate'; degrees: number; speedStepsPerS?: number | undefined };

/** A motion the robot reported finished. */
export interface MotionDone {
  moveId: number;
  /** The steps each wheel made. */
  leftSteps: number;
  rightSteps: number;
  /** The duration the robot planned for it, ms. */
  plannedDurationMs: number;
}

/** A `drive` as the robot took it: the wheel speeds it runs at, and its end when it has one. */
export interface DriveDone {
  moveId: number;
  /** Signed wheel speeds, steps/s, after the robot's top-speed clamp. */
  leftSps: number;
  rightSps: number;
  /** Whether the robot scaled both speeds down to its top speed. */
  speedClamped: boolean;
  /** True when the drive runs on after the call (no duration): ended by stop() or a new motion. */
  running: boolean;
  /** The steps each wheel made, when the drive had a duration and ran to its end. */
  leftSteps?: number;
  rightSteps?: number;
}

/**
 * An emergency stop as the robot acknowledged it. `delivered` is false when there was no link to
 * send it over (before `initialize()`, after `cleanup()`): the host latched, and the robot is
 * latched as soon as a session opens. The motion fields say which motion it ended and where.
 */
export interface EmergencyStopDone {
  estop: boolean;
  reason: string;
  delivered: boolean;
  moveId?: number;
  moveOutcome?: string;
  leftSteps?: number;
  rightSteps?: number;
  /** The robot's clock when the wheels stopped, µs. */
  robotEstopUs?: number;
}

/** The parts of a robot a port may lack; a call on a missing one is NOT_IMPLEMENTED. */
export type RobotPart = 'camera' | 'range sensors' | 'line sensors' | 'IMU' | 'speaker';

/** The capability each part stands for (the `details.capability` of its NOT_IMPLEMENTED). */
export const ROBOT_PART_CAPABILITY: Readonly<Record<RobotPart, string>> = Object.freeze({
  camera: CAPABILITIES.camera,
  'range sensors': CAPABILITIES.rangeSensors,
  'line sensors': CAPABILITIES.lineSensors,
  IMU: CAPABILITIES.imu,
  speaker: CAPABILITIES.speaker,
});

/** What a speaker does. */
export interface RobotSpeaker {
  speak(text: string, urgency: 'info' | 'warning' | 'alert'): Promise<void>;
  playSound(soundId: string): Promise<void>;
}

/**
 * The robot a HAL drives, as the commands it understands and the sensors it has: what a binding
 * (the wire session to a cube, the simulated world's robot) implements so that one HAL class
 * serves both worlds. Every parameter reaching a port has been validated by the HAL's boundary;
 * every failure is a HalError naming what failed.
 *
 * Motions resolve when the robot reports them ended: a finished one with its steps, an
 * interrupted one with the HalError its outcome calls for (EMERGENCY_STOPPED, INTERRUPTED,
 * COLLISION, TIMEOUT, NOT_CONNECTED saying whether a stop was acknowledged).
 */
export interface RobotPort {
  readonly mode: HALMode;
  /** Opens the robot: a session with the cube, a place in the world. */
  open(): Promise<void>;
  /** Stops the motors and lets the robot go. Safe to call twice, and before `open()`. */
  close(): Promise<void>;
  /** Whether the robot can be reached now (the link is up). */
  isConnected(): boolean;
  /** The clock results are stamped with, ms. */
  now(): number;
  /** The geometry and limits calls are validated against (as the robot reports them). */
  config(): RobotConfig;
  deviceInfo(): DeviceInfo;
  /** The pose the robot's odometry gives, in the frame the HAL reports. */
  pose(): Pose;
  /** Runs one motion to its end. */
  motion(command: MotionCommand): Promise<MotionDone>;
  /** Velocity mode at signed steps/s per wheel; waits for its end when it has a duration. */
  drive(leftSps: number, rightSps: number, durationMs?: number): Promise<DriveDone>;
  /** Stops any motion; resolves whether one was running, only once the robot acknowledged it. */
  stop(): Promise<boolean>;
  /** Latches the emergency stop (never refused, even before `open()`). */
  emergencyStop(reason: string): Promise<EmergencyStopDone>;
  /** Clears the latch; resolves whether it was set. */
  resetEmergencyStop(): Promise<boolean>;
  /** Whether motion is refused by a latched emergency stop (cached; never throws). */
  isEmergencyStopped(): boolean;
  /** The safety state (cached; never throws). */
  safetyStatus(): SafetyStatus;
  setLed(led: LedSetting): Promise<LitLed>;
  /** Records a message of the HAL's log where this world keeps it (never throws). */
  log(message: string, level: HALLogLevel): void;
  /** Reports a `log` call the boundary refused, at warn level, where this world logs (never throws). */
  logRefused(refusal: { code?: string | undefined; error?: string | undefined }): void;
  /** Calls `listener` whenever the robot's configuration changes (a hello, a calibration). */
  onConfigChanged?(listener: () => void): void;
  /** The error of a call on a part the robot lacks (NOT_IMPLEMENTED, in this world's words). */
  lacks(part: RobotPart): Error;
  /** Refuses a `moveTo` target the robot cannot reach (the simulated arena's walls). */
  checkTarget?(x: number, y: number): void;
  captureFrame?(): Promise<string>;
  scan?(mode: 'full' | 'targeted' | 'quick'): Promise<ScanResult>;
  distanceSensors?(): Promise<DistanceSensors>;
  /** A measured IMU; without one the HAL reports the heading and turn rate of the odometry. */
  imu?(): IMUReading;
  readonly speaker?: RobotSpeaker;
}

/**
 * How a safety status names the robot's last trip (a step-limit or host-timeout stop, an e-stop)
 * in its `errors`, in both worlds.
 */
export function lastTripError(trip: { reason: string; detail: string }): string {
  return `last trip: ${trip.reason} (${trip.detail})`;
}
