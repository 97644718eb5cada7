export { HybridHAL } from './hybrid-hal.js';
export type { DivergenceEvent, TwinSummary } from './hybrid-hal.js';
export type { HybridHALOptions, HybridLogger, HybridLogLevel } from './options.js';
export {
  composePose,
  DEFAULT_DIVERGENCE_TOLERANCE,
  divergenceBetween,
  normalizeAngle,
  planar,
  relativeTo,
} from './divergence.js';
export type { Divergence, DivergenceTolerance, PlanarPose } from './divergence.js';
export { mergeSafetyStatus } from './safety.js';
