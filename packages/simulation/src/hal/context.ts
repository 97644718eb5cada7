import type { TypedEmitter } from '@hal/types';
import type { SimRobot } from '../robot/sim-robot.js';
import type { World } from '../world.js';
import type { SimulationHALEvents } from './events.js';
import type { SimulationClock, SimulationHALOptions } from './options.js';

/** What waiting for a simulated motion needs: the world, its clock and where to report. */
export interface HalContext {
  readonly world: World;
  /** The simulated robot, looked up by id on each call (a map change re-creates it). */
  robot(): SimRobot;
  readonly events: TypedEmitter<SimulationHALEvents>;
  readonly clock: SimulationClock;
  readonly options: SimulationHALOptions;
}
