export { serveHal } from './serve-hal.js';
export { SERVE_DEFAULTS } from './options.js';
export type { HalServer, ServeHalOptions } from './options.js';
export { checkBinding, isLoopback } from './auth.js';
