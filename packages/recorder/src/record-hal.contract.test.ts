import { SimulationHAL } from '@hal/simulation';
import { describeHalContract } from '@hal/types/testing';
import { memorySink } from './file-sink.js';
import { recordHal } from './record-hal.js';
import { McapRecorder } from './recorder.js';

// A recorded HAL behaves exactly as the HAL it wraps: the whole contract suite, through the proxy.
describeHalContract('recordHal(SimulationHAL)', {
  create: async () => recordHal(new SimulationHAL(), await McapRecorder.create(memorySink())),
  positionTolerance: 0.002,
  yawTolerance: 0.002,
});
