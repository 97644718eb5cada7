import { describeHalContract } from './contract.js';
import { ReferenceHAL } from './reference-hal.fixture.js';

describeHalContract('ReferenceHAL', { create: () => new ReferenceHAL() });
