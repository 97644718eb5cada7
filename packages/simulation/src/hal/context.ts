import type { HalBoundary, TypedEmitter } from '@hal/types';
import type { SimRobot } from '../robot/sim-robot.js';
import type { World } from '../world.js';
import type { SimulationHALEvents } from './events.js';
import type { SimulatedFeatures, SimulationClock, SimulationHALOptions } from './options.js';

/** What a SimulationHAL shares with its subsystems (locomotion, vision, communication, safety). */
export interface HalContext {
  readonly world: World;
  /** The simulated robot, looked up by id on each call (a map change re-creates it). */
  robot(): SimRobot;
  /** Readiness, e-stop gating, validation, timing and error-to-result conversion of each call. */
  readonly boundary: HalBoundary;
  readonly events: TypedEmitter<SimulationHALEvents>;
  readonly clock: SimulationClock;
  readonly features: Required<SimulatedFeatures>;
  readonly options: SimulationHALOptions;
}
