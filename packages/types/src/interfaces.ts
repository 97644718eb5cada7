import type { HALMode } from './mode.js';
import type {
  DeviceInfo,
  DistanceSensors,
  IMUReading,
  Pose,
  SafetyStatus,
  ScanResult,
} from './pose.js';
import type { HALToolResult } from './result.js';
import type { RobotConfig } from './robot-config.js';

/*
 * The five-subsystem contract. Every implementation (simulation, physical, hybrid) must:
 * - validate every parameter before anything moves (non-finite, wrong type: INVALID_PARAMETER;
 *   out of the robot's limits: RANGE_EXCEEDED), and change nothing when validation fails;
 * - refuse motion at once with EMERGENCY_STOPPED while the emergency stop is latched;
 * - resolve a motion call when the motion has finished or failed, never hang: every wait has a
 *   timeout derived from the motion profile, and a timeout is `success: false`, code TIMEOUT;
 * - report a capability the robot lacks honestly: absent from `capabilities`, its result-returning
 *   calls fail with NOT_IMPLEMENTED, and its value-returning calls reject with a HalError of code
 *   NOT_IMPLEMENTED or return a value derived from what the robot has, marked with its `source`;
 * - put every call through the shared boundary (`HalBoundary`), with the same rules in the same
 *   order on every HAL: before `initialize()` and after `cleanup()` NOT_READY, then (motion only)
 *   EMERGENCY_STOPPED, then parameters, then the capability. A call that answers with a
 *   `HALToolResult` never throws: it resolves `success: false` with the code. A call that answers
 *   with a value (`getPose`, `captureFrame`, `scan`, `getDistanceSensors`, `getLineSensors`,
 *   `getIMU`) rejects with a `HalError` carrying the code. `log` never throws. The synchronous
 *   `isEmergencyStopped()` and `getSafetyStatus()` answer from cached state at any time and never
 *   throw, so a safety check cannot fail.
 * Frame REP-103: x forward, y left, yaw counter-clockwise positive. Metres unless a name says cm.
 */

/** Wheel motion. Every motion call resolves when the motion has finished. */
export interface LocomotionInterface {
  /**
   * Differential drive by wheel power.
   * @param left - left wheel power, -255..255 (negative: backwards); scaled to the top wheel speed
   * @param right - right wheel power, -255..255
   * @param durationMs - stop after this many milliseconds; without it the wheels keep turning
   *   until `stop()` (or the robot's host timeout, should the host go silent)
   */
  drive(left: number, right: number, durationMs?: number): Promise<HALToolResult>;

  /**
   * Drive to a point: turn toward it in place, then go straight. Resolves on arrival.
   * @param x - target x, metres (world frame)
   * @param y - target y, metres
   * @param z - target z, metres (ignored by wheeled robots; must be finite)
   * @param speed - cruise speed, m/s; default the robot's top speed
   */
  moveTo(x: number, y: number, z: number, speed?: number): Promise<HALToolResult>;

  /**
   * Turn in place.
   * @param direction - 'left' is counter-clockwise (yaw increases), 'right' clockwise
   * @param degrees - how far, degrees, > 0
   */
  rotate(direction: 'left' | 'right', degrees: number): Promise<HALToolResult>;

  /** Drive straight ahead `distanceCm` centimetres (> 0). */
  moveForward(distanceCm: number): Promise<HALToolResult>;

  /** Drive straight back `distanceCm` centimetres (> 0). */
  moveBackward(distanceCm: number): Promise<HALToolResult>;

  /** Stop all wheel motion now (no ramp-down). Always allowed, even while emergency-stopped. */
  stop(): Promise<HALToolResult>;

  /**
   * The current pose (REP-103; metres, radians, m/s, rad/s). Rejects with a HalError:
   * NOT_READY before `initialize()` and after `cleanup()`.
   */
  getPose(): Promise<Pose>;
}

/** Camera and range sensing. */
export interface VisionInterface {
  /**
   * The latest camera frame as a base64 JPEG data URL (`data:image/jpeg;base64,...`). Rejects
   * with a HalError: NOT_READY before `initialize()` and after `cleanup()` (and starts nothing);
   * NOT_IMPLEMENTED without a camera; TIMEOUT when no frame comes in time.
   */
  captureFrame(): Promise<string>;

  /**
   * A scan of the surroundings; robots without range sensors derive what they can. Rejects with
   * a HalError: NOT_READY; INVALID_PARAMETER for a mode other than 'full', 'targeted' or 'quick'
   * (default 'quick'); NOT_IMPLEMENTED when the robot cannot scan.
   */
  scan(mode?: 'full' | 'targeted' | 'quick'): Promise<ScanResult>;

  /** Range readings front/left/right, metres. Rejects NOT_READY, or NOT_IMPLEMENTED without sensors. */
  getDistanceSensors(): Promise<DistanceSensors>;

  /** Line sensor readings, 0..1 each, left to right. Rejects NOT_READY, or NOT_IMPLEMENTED. */
  getLineSensors(): Promise<number[]>;

  /**
   * Acceleration, rotation rate and heading; `source` says where each comes from. Rejects with a
   * HalError: NOT_READY before `initialize()` and after `cleanup()`.
   */
  getIMU(): Promise<IMUReading>;
}

/** A robot arm and gripper. Optional: wheeled robots leave it undefined. */
export interface ManipulationInterface {
  /** Move the end effector to a point, metres, robot frame. */
  moveTo(x: number, y: number, z: number, speed?: number): Promise<HALToolResult>;
  /** Close, open or hold the gripper with a force, percent 0..100. */
  grasp(force: number, mode?: 'open' | 'close' | 'hold'): Promise<HALToolResult>;
  /** Extend the arm by `distance` metres. */
  extend(distance: number): Promise<HALToolResult>;
  /** Retract the arm fully. */
  retract(): Promise<HALToolResult>;
  /** Trade speed for precision. */
  setPrecisionMode(enabled: boolean): Promise<HALToolResult>;
  /** End effector position, metres, robot frame. */
  getPosition(): Promise<{ x: number; y: number; z: number }>;
}

/** Log levels for {@link CommunicationInterface.log}. */
export type HALLogLevel = 'debug' | 'info' | 'warn' | 'error';

/** Speaking, lights, sounds and telemetry logging. */
export interface CommunicationInterface {
  /** Say `text` through the robot's speaker. */
  speak(text: string, urgency?: 'info' | 'warning' | 'alert'): Promise<HALToolResult>;
  /** Set the status LED: r, g, b 0..255 each, and a pattern (default solid). */
  setLED(
    r: number,
    g: number,
    b: number,
    pattern?: 'solid' | 'blink' | 'pulse',
  ): Promise<HALToolResult>;
  /** Play a sound effect by id. */
  playSound(soundId: string): Promise<HALToolResult>;
  /**
   * Record a message (a string of up to 2000 characters) in the HAL's log and telemetry, at
   * `level` (default 'info'). Never throws: a call the boundary refuses (not ready, a message that
   * is not a string, an unknown level) records nothing and is reported through the HAL's logger.
   */
  log(message: string, level?: HALLogLevel): void;
}

/** Emergency stop and safety state. */
export interface SafetyInterface {
  /** Stop everything now and latch: motion is refused until {@link resetEmergencyStop}. */
  emergencyStop(reason?: string): Promise<HALToolResult>;
  /**
   * Whether the emergency stop is latched. Synchronous: answers from cached state at any time,
   * before `initialize()` and after `cleanup()` too, and never throws.
   */
  isEmergencyStopped(): boolean;
  /** Clear a latched emergency stop. The only way to clear it. */
  resetEmergencyStop(): Promise<HALToolResult>;
  /**
   * Battery, temperature, active faults and recorded trips, from cached state. Answers at any
   * time (before `initialize()` and after `cleanup()` with what is known) and never throws; its
   * `emergencyStopped` always equals {@link isEmergencyStopped}.
   */
  getSafetyStatus(): SafetyStatus;
}

/** One robot, driven the same way whichever world it lives in. */
export interface HardwareAbstractionLayer {
  /** Which world this HAL drives. */
  mode: HALMode;
  locomotion: LocomotionInterface;
  vision: VisionInterface;
  /** Present only when the robot has an arm. */
  manipulation?: ManipulationInterface;
  communication: CommunicationInterface;
  safety: SafetyInterface;
  /** Connect and get ready; rejects with a HalError when the robot cannot be reached. */
  initialize(): Promise<void>;
  /** Stop the motors and release every resource. Safe to call twice. */
  cleanup(): Promise<void>;
  /** True between a successful `initialize()` and `cleanup()`, while the robot is reachable. */
  isReady(): boolean;
  /** Who the robot is and which capability strings it offers. */
  getDeviceInfo(): DeviceInfo;
  /**
   * Optional: the geometry and limits this HAL validates calls against (for a physical robot, the
   * limits it reported when the session opened). Tools read their parameter bounds from it; a HAL
   * without it is taken to be the V1 robot.
   */
  readonly robotConfig?: RobotConfig;
}
