import { describeHalContract } from './contract.js';
import { ReferenceHAL } from './reference-hal.js';

describeHalContract('ReferenceHAL', { create: () => new ReferenceHAL() });
