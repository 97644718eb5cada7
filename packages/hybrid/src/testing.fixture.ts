import { PhysicalHAL } from '@hal/physical';
import { MockRobot } from '@hal/physical/testing';
import type { PhysicalHALOptions } from '@hal/physical';
import { SimulationHAL } from '@hal/simulation';
import type { SimulationHALOptions } from '@hal/simulation';
import { HybridHAL } from './hybrid-hal.js';
import type { HybridHALOptions } from './options.js';

/** The mock robot's clock runs this much faster than real time (10 s host timeout = 200 ms). */
export const TIME_SCALE = 50;

export interface HybridRig {
  hal: HybridHAL;
  robot: MockRobot;
  physical: PhysicalHAL;
  twin: SimulationHAL;
}

/** A HybridHAL over an in-process mock robot and a fresh simulated twin. */
export function hybridRig(
  options: {
    twin?: SimulationHALOptions;
    physical?: PhysicalHALOptions;
    hybrid?: Partial<HybridHALOptions>;
  } = {},
): HybridRig {
  const robot = new MockRobot({ timeScale: TIME_SCALE, hostTimeoutMs: 10_000 });
  const physical = new PhysicalHAL(
    { mode: 'physical', deviceId: 'cube-1' },
    { transport: robot.transport(), timeScale: TIME_SCALE, ...options.physical },
  );
  const twin = new SimulationHAL({ deviceId: 'cube-1-twin', ...options.twin });
  const hal = new HybridHAL({ physical, twin, ...options.hybrid });
  return { hal, robot, physical, twin };
}
