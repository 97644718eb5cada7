export { serveFoxglove } from './serve-foxglove.js';
export { FOXGLOVE_DEFAULTS } from './options.js';
export type {
  FoxgloveLiveServer,
  FoxgloveServeOptions,
  FoxgloveStats,
  ViewerDrops,
} from './options.js';
export { DESKTOP_ORIGIN } from './door.js';
export { liveNames, LIVE_SCHEMAS } from './topics.js';
export type { ControlNames, LiveTopic } from './topics.js';
export { powersOfTwist } from './teleop.js';
