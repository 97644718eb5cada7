export { serveHal } from './serve-hal.js';
export { SERVE_DEFAULTS } from './options.js';
export type { HalServer, ServeHalOptions } from './options.js';
export { checkBinding, doorRefusal, refuseUpgrade } from './auth.js';
export type { DoorRefusal, DoorWords } from './auth.js';
/** Re-exported from `@hal/types`, where every server of a HAL finds it. */
export { isLoopback } from '@hal/runtime';
