export { serveHal } from './serve-hal.js';
export { SERVE_DEFAULTS } from './options.js';
export type { HalServer, ServeHalOptions } from './options.js';
export { checkBinding, isLoopback } from './auth.js';
export { silentRemoteLogger } from '../logger.js';
export type { RemoteLogLevel, RemoteLogger } from '../logger.js';
