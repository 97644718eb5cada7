import { describeHalContract } from '@hal/types/testing';
import { SimulationHAL } from './hal.js';

describeHalContract('SimulationHAL', {
  create: () => new SimulationHAL(),
  positionTolerance: 0.002,
  yawTolerance: 0.002,
});
