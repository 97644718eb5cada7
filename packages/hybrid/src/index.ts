export { HybridHAL } from './hybrid-hal.js';
export type { DivergenceEvent, TwinSummary } from './hybrid-hal.js';
export type { HybridHALOptions } from './options.js';
export { DEFAULT_DIVERGENCE_TOLERANCE, planar } from './divergence.js';
export type { Divergence, DivergenceTolerance } from './divergence.js';
