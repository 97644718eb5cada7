import { RobotHAL } from '@hal/runtime';
import type { HALConfig, TypedEmitter } from '@hal/types';
import type { SimRobot } from '../robot/sim-robot.js';
import type { World } from '../world.js';
import type { SimulationHALEvents } from './events.js';
import { optionsFromConfig } from './from-config.js';
import type { SimulationHALOptions } from './options.js';
import { WorldBinding } from './world-binding.js';

/**
 * The HAL of a simulated robot: the one {@link RobotHAL} over the simulated world's robot
 * ({@link WorldBinding}). Each call is the firmware command a PhysicalHAL sends for it (see
 * docs/simulation.md), executed by a {@link SimRobot} that moves as the firmware does.
 */
export class SimulationHAL extends RobotHAL<WorldBinding> {
  declare readonly mode: 'simulation';

  constructor(options: SimulationHALOptions = {}) {
    super(new WorldBinding(options));
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

  /** The world the robot lives in. */
  get world(): World {
    return this.binding.world;
  }

  /** What happens as it happens: motions, the LED and the log, the e-stop. */
  get events(): TypedEmitter<SimulationHALEvents> {
    return this.binding.events;
  }

  /** The simulated robot this HAL drives (looked up by id: a map change re-creates it). */
  get robot(): SimRobot {
    return this.binding.robot;
  }

  /**
   * Simulates the host going silent (no heartbeats between commands): a running motion stops
   * after the robot's host timeout, as the firmware's does. `false` makes the host talk again.
   */
  simulateHostSilence(silent: boolean): void {
    this.binding.simulateHostSilence(silent);
  }
}
