export { HybridHAL } from './hybrid-hal.js';
export type { DivergenceEvent, TwinSummary } from './hybrid-hal.js';
export type { HybridHALOptions } from './options.js';
export {
  composePose,
  DEFAULT_DIVERGENCE_TOLERANCE,
  divergenceBetween,
  planar,
  relativeTo,
} from './divergence.js';
export type { Divergence, DivergenceTolerance } from './divergence.js';
export { mergeSafetyStatus } from './safety.js';
