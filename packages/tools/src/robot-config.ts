import { V1_ROBOT } from '@hal/types';
import type { HardwareAbstractionLayer, RobotConfig } from '@hal/types';

/**
 * The limits a HAL validates against: its `robotConfig` when it exposes one (PhysicalHAL: what the
 * robot reported; SimulationHAL: the simulated robot's), else the V1 robot.
 */
export function robotConfigOf(hal: HardwareAbstractionLayer): RobotConfig {
  const config = hal.robotConfig;
  return config !== undefined && typeof config.wheelDiameterCm === 'number' ? config : V1_ROBOT;
}
