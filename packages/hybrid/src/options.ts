import type { CallTable, HardwareAbstractionLayer, Logger, RobotConfig } from '@hal/types';
import type { DivergenceTolerance } from './divergence.js';

/** What a {@link HybridHAL} is made of. */
export interface HybridHALOptions {
  /** The physical robot's HAL (e.g. a PhysicalHAL): its results and pose are the truth. */
  physical: HardwareAbstractionLayer;
  /** The simulated twin (e.g. a SimulationHAL): it runs every motion too, and is compared. */
  twin: HardwareAbstractionLayer;
  /** When the twin counts as diverged. Default 5 mm and 1 degree. */
  divergence?: Partial<DivergenceTolerance>;
  /** Where to log (namespace `hal:hybrid`). Default silent. */
  logger?: Logger;
  /** The id `getDeviceInfo()` reports. Default the physical robot's id. */
  deviceId?: string;
  /**
   * The limits calls are validated against before either robot is asked. Default the physical
   * HAL's `robotConfig` when it has one (PhysicalHAL does: the robot's reported limits), else V1.
   */
  robotConfig?: () => RobotConfig;
  /** The clock results are stamped with, ms. Default `Date.now`. */
  now?: () => number;
  /** The calls this HAL offers, run on both robots as their kind says; default the HAL's own. */
  calls?: CallTable;
  /**
   * 'physical' (default): at `initialize()` the twin (a SimulationHAL) takes the physical robot's
   * wheel diameter, wheel base and steps per revolution, calibrated values included. 'own': the
   * twin keeps the geometry it was built with (to study a twin that differs on purpose).
   */
  twinGeometry?: 'physical' | 'own';
}
