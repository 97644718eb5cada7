import { describeHalContract } from '@hal/types/testing';
import { SimulationHAL } from './simulation-hal.js';

// The HAL advances the clock itself until each motion ends.
describeHalContract('SimulationHAL (fast clock)', {
  create: () => new SimulationHAL(),
  positionTolerance: 0.002,
  yawTolerance: 0.002,
});

// A real-time ticker (here 200 times faster than real time) advances the clock; the HAL waits.
describeHalContract('SimulationHAL (real-time clock)', {
  create: () => new SimulationHAL({ clock: 'realtime', realtimeSpeed: 200 }),
  positionTolerance: 0.002,
  yawTolerance: 0.002,
});
