export { serveFoxglove } from './serve-foxglove.js';
export { FOXGLOVE_DEFAULTS } from './options.js';
export type {
  FoxgloveLiveServer,
  FoxgloveServeOptions,
  FoxgloveStats,
  ViewerDrops,
} from './options.js';
