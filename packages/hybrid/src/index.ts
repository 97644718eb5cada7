export { HybridHAL } from './hybrid-hal.js';
export type { DivergenceEvent } from './hybrid-hal.js';
export type { HybridHALOptions } from './options.js';
export type { Divergence, DivergenceTolerance } from './divergence.js';
